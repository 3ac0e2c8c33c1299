//! The C player of compressed tables (`NAME_RUNS`): its type, its inline
//! step path, and what the shared planner asks of it, on positions along a
//! table of runs (`cursor.rs`).
//!
//! A run is played with the recurrence of `runs::Expand` (`x = frac +
//! interval; period = x >> 16; frac = x & 0xFFFF; interval += add`), the
//! remainder `frac` in 16 bits, as the Rust player plays it: forwards from a
//! run's first step, backwards from its last with the remainder's complement
//! and `-add` (the reflected edges' ceiling differences). The remainder
//! carries from run to run either way, so that entering the next run forwards
//! reads its words, and entering the previous run backwards reads its words
//! and computes its last step's interval (one multiplication per run).
//!
//! `@T@` is the player's prefix (`ramps_runs_player`), `@S@` the storage word
//! and a space (or nothing), `@R@` the macro that reads one word of a table.

/// The type, the functions' declarations and the inline step path.
pub(super) const API: &str = r#"/* A stretch of a move: steps reading one table at positions that move the
 * same way, and the state its first run starts from. Part of @T@_t. */
typedef struct {
    uint16_t count_hi;          /* steps not yet handed to the step path: */
    uint16_t count_lo;          /* count_hi * 65536 + count_lo */
    uint32_t total;             /* steps in all */
    uint32_t acc;               /* where the acceleration side stands at its start */
    uint32_t interval;          /* its first step's interval, 16.16 */
    uint32_t add;               /* added after each step of its first run */
    uint16_t frac;              /* the edges' sub-tick remainder before it */
    uint16_t first;             /* steps of its first run */
    const @S@uint16_t *run;     /* the words of the run it reads first */
    signed char dir;            /* positions per step: 1, -1 or 0 */
    signed char acc_dir;        /* the acceleration side's move per step */
    unsigned char decel;        /* it reads the deceleration table */
    unsigned char decelerating; /* the deceleration table has taken over */
} @T@_stretch_t;

/* Plays moves from an acceleration table and a deceleration table of runs
 * (NAME_RUNS, slowest first; one table for both is fine), as the Rust
 * `Player::compressed` does. Its fields are the player's own: use the
 * functions. Start, stop, change the cruise and count what remains between
 * two steps: from the step interrupt, or with it masked. */
typedef struct {
    uint32_t interval;      /* the next step's interval, 16.16 */
    uint32_t add;           /* added after each step, two's complement */
    uint16_t frac;          /* the edges' sub-tick remainder */
    unsigned char left;     /* steps before the next refill */
    uint16_t rest;          /* steps of the run taken, after those */
    const @S@uint16_t *run; /* the words of the run being played */
    @T@_stretch_t *cur;     /* the stretch being played */
    @T@_stretch_t *end;     /* past the plan's last stretch */
    unsigned char len;      /* stretches in the plan */
    @T@_stretch_t plan[8];
    uint32_t before;        /* the period played before the plan began */
    const @S@uint16_t (*accel)[5];
    const @S@uint16_t (*decel)[5];
    uint16_t accel_runs, decel_runs;
    uint32_t accel_last, decel_last, decel_fastest, decel_slack, cap, cruise;
    unsigned char empty;
} @T@_t;

/* Plays from `accel` (`accel_runs` runs) up and `decel` (`decel_runs` runs)
 * down, both ordered slow to fast; at rest. */
void @T@_init(@T@_t *p, const @S@uint16_t (*accel)[5], uint16_t accel_runs,
    const @S@uint16_t (*decel)[5], uint16_t decel_runs) STEPPER_PROFILES_REENTRANT;
/* Starts a move of `steps` steps from rest, cruising at the acceleration
 * table's top. */
void @T@_start(@T@_t *p, uint32_t steps) STEPPER_PROFILES_REENTRANT;
/* Decelerates along the deceleration table from the current speed to rest. */
void @T@_stop(@T@_t *p) STEPPER_PROFILES_REENTRANT;
/* Cruises at step `pos` of the acceleration table (clamped to it) instead of
 * its top, walking there one step per step. */
void @T@_set_cruise(@T@_t *p, uint32_t pos) STEPPER_PROFILES_REENTRANT;
/* Steps left in the move. */
uint32_t @T@_remaining(const @T@_t *p) STEPPER_PROFILES_REENTRANT;

/* The next run of the plan to the step path (at most 255 steps of it at
 * once); 0 when the plan is played. Called by the step path at a run's end:
 * out of line, so that a step interrupt saves for the step path only the
 * registers the call may change. */
unsigned char @T@_refill_(@T@_t *p) STEPPER_PROFILES_REENTRANT;

/* Plays the next step: writes its period, in ticks, to `*period` and returns
 * 1, or returns 0 once the move is done. A countdown and the run's additions
 * (16 bits for the remainder, 32 for the interval): no division, no
 * multiplication. At a run's end, and every 255 steps, a refill. The form a
 * step interrupt costs least with. */
STEPPER_PROFILES_INLINE unsigned char @T@_step(@T@_t *p, uint16_t *period)
    STEPPER_PROFILES_REENTRANT
{
    uint32_t interval, x;
    unsigned char left = p->left;
    if (STEPPER_PROFILES_UNLIKELY(left == 0)) {
        if (!@T@_refill_(p)) {
            return 0;
        }
        left = p->left;
    }
    p->left = (unsigned char)(left - 1);
    interval = p->interval;
    p->interval = interval + p->add;
    x = interval + p->frac;
    p->frac = (uint16_t)x;
    *period = (uint16_t)(x >> 16);
    return 1;
}

/* The period of the next step, in ticks; 0 once the move is done. */
STEPPER_PROFILES_INLINE uint16_t @T@_next(@T@_t *p) STEPPER_PROFILES_REENTRANT
{
    uint16_t period;
    return @T@_step(p, &period) ? period : 0;
}

"#;

/// The refill, which the step path calls at a run's end.
pub(super) const REFILL: &str = r#"/* Two words of a run as one 32-bit value, high word first; one read per
 * statement, whatever the read macro does. */
STEPPER_PROFILES_INLINE uint32_t @T@_word32_(const @S@uint16_t *w) STEPPER_PROFILES_REENTRANT
{
    uint32_t high = @R@(w);
    return (high << 16) | @R@(w + 1);
}

/* Hands the step path `n` steps, at most 255 at once; the rest later. */
STEPPER_PROFILES_INLINE unsigned char @T@_pieces_(@T@_t *p, uint16_t n)
    STEPPER_PROFILES_REENTRANT
{
    p->left = (unsigned char)(n > 255 ? 255 : n);
    p->rest = (uint16_t)(n - p->left);
    return 1;
}

/* At most `n` steps of stretch `s`, taken from its count. */
STEPPER_PROFILES_INLINE uint16_t @T@_count_down_(@T@_stretch_t *s, uint16_t n)
    STEPPER_PROFILES_REENTRANT
{
    if (s->count_hi == 0 && n > s->count_lo) {
        n = s->count_lo;
    }
    if (n > s->count_lo) {
        s->count_hi--;
    }
    s->count_lo = (uint16_t)(s->count_lo - n);
    return n;
}

/* The step path enters the next stretch with steps, from the state planned
 * for it; 0 when the plan is played. */
STEPPER_PROFILES_NOINLINE static unsigned char @T@_next_stretch_(@T@_t *p)
    STEPPER_PROFILES_REENTRANT
{
    @T@_stretch_t *s = p->cur;
    do {
        if (++s >= p->end) {
            return 0;
        }
    } while ((s->count_hi | s->count_lo) == 0);
    p->cur = s;
    p->interval = s->interval;
    p->add = s->add;
    p->frac = s->frac;
    p->run = s->run;
    return @T@_pieces_(p, @T@_count_down_(s, s->first));
}

/* The step path enters the run before its run, backwards: from its last
 * step, whose interval is interval + (count - 1) * add, with -add. On SDCC's
 * 8051 port the product is shifts and additions: its library multiplies
 * longs through an operand in static memory, which the step interrupt would
 * overwrite under a multiplication it interrupts. */
STEPPER_PROFILES_NOINLINE static unsigned char @T@_backwards_(@T@_t *p)
    STEPPER_PROFILES_REENTRANT
{
    const @S@uint16_t *r = p->run;
    uint32_t interval, add;
    uint16_t n, m;
    do {
        r -= 5;
        n = @R@(r);
    } while (n == 0);
    p->run = r;
    interval = @T@_word32_(r + 1);
    add = @T@_word32_(r + 3);
    p->add = 0 - add;
    m = (uint16_t)(n - 1u);
#if defined(__SDCC_mcs51)
    for (; m != 0; m >>= 1, add <<= 1) {
        if (m & 1u) {
            interval += add;
        }
    }
#else
    interval += m * add;
#endif
    p->interval = interval;
    return @T@_pieces_(p, @T@_count_down_(p->cur, n));
}

/* The step path's refill. Most often the next run forwards: its five words
 * read, 16-bit counts. */
unsigned char @T@_refill_(@T@_t *p) STEPPER_PROFILES_REENTRANT
{
    const @S@uint16_t *r;
    uint16_t n = p->rest;
    signed char dir;
    if (n != 0) {
        return @T@_pieces_(p, n);
    }
    if ((p->cur->count_hi | p->cur->count_lo) == 0) {
        return @T@_next_stretch_(p);
    }
    dir = p->cur->dir;
    if (dir < 0) {
        return @T@_backwards_(p);
    }
    if (dir == 0) {
        /* Held: the same period again. */
        return @T@_pieces_(p, @T@_count_down_(p->cur, 0xFFFFu));
    }
    r = p->run;
    do {
        r += 5;
        n = @R@(r);
    } while (n == 0);
    p->run = r;
    @T@_pieces_(p, @T@_count_down_(p->cur, n));
    p->interval = @T@_word32_(r + 1);
    p->add = @T@_word32_(r + 3);
    return 1;
}

"#;

/// Where a stretch starts and the definitions the shared planner uses,
/// after the positions along a table of runs (`cursor.rs`).
pub(super) const DEFINITIONS: &str = r#"/* Where a stretch starts, noted in its interval until the plan is made:
 * `_settle_` finds the state it plays from then, so that the search for it
 * runs below the planner's call, not below the planner's own calls. */
static void @T@_place_(@T@_t *p, @T@_stretch_t *s, uint32_t pos) STEPPER_PROFILES_REENTRANT
{
    (void)p;
    s->interval = pos;
}

/* The state a stretch starting at step `pos` plays its first run from: its
 * first step's remainder and interval forwards; backwards the complement of
 * the remainder after it and `-add`; held, its period with no remainder. */
static void @T@_locate_(@T@_t *p, @T@_stretch_t *s, uint32_t pos) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL @T@_cursor_t c;
    STEPPER_PROFILES_LOCAL uint32_t n;
    c.decel = s->decel;
    c.pos = pos;
    @T@_place_cursor_(p, &c);
    s->run = (s->decel ? p->decel : p->accel)[c.entry];
    if (s->dir > 0) {
        n = c.in_table ? c.count : s->total;
        n = n > c.within ? n - c.within : 1;
        s->frac = c.frac;
        s->interval = c.interval;
        s->add = c.add;
    } else if (s->dir < 0) {
        n = (uint32_t)c.within + 1;
        s->frac = (uint16_t)(0xFFFFu - (uint16_t)(c.frac + c.interval));
        s->interval = c.interval;
        s->add = 0 - c.add;
    } else {
        n = 0xFFFFu;
        s->frac = 0;
        s->interval = @T@_cperiod_(&c) << 16;
        s->add = 0;
    }
    if (n > s->total) {
        n = s->total;
    }
    s->first = n > 0xFFFFu ? 0xFFFFu : (uint16_t)n;
}

/* The state every stretch of the plan plays from, once the plan is made. */
static void @T@_settle_(@T@_t *p) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL unsigned char i;
    for (i = 0; i < p->len; i++) {
        @T@_locate_(p, &p->plan[i], p->plan[i].interval);
    }
}

/* The step path enters stretch `s`, from the state planned for it. */
static void @T@_enter_(@T@_t *p, const @T@_stretch_t *s) STEPPER_PROFILES_REENTRANT
{
    p->interval = s->interval;
    p->add = s->add;
    p->frac = s->frac;
    p->run = s->run;
}

/* Steps of stretch `s` the step path takes first. */
static uint16_t @T@_first_(const @T@_stretch_t *s) STEPPER_PROFILES_REENTRANT
{
    return s->first;
}

/* The period of the step played last, from the step path's state: the
 * interval before the last addition and the remainder after it. */
static uint32_t @T@_last_(const @T@_t *p) STEPPER_PROFILES_REENTRANT
{
    return (p->interval - p->add - p->frac + 0xFFFFul) >> 16;
}

/* The first of the last `r` steps at which the deceleration table, read at
 * the steps that remain, is not faster than the acceleration side walking
 * from `pos` towards the cruise position; `r` if none is. */
static uint32_t @T@_crossing_(const @T@_t *p, uint32_t pos, uint32_t r)
    STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL @T@_cursor_t d, a;
    STEPPER_PROFILES_LOCAL uint32_t j;
    d.decel = 1;
    d.pos = r - 1;
    @T@_place_cursor_(p, &d);
    a.decel = 0;
    a.pos = pos;
    @T@_place_cursor_(p, &a);
    for (j = 0; j < r; j++) {
        if (@T@_cperiod_(&d) >= @T@_cperiod_(&a)) {
            return j;
        }
        @T@_backward_(p, &d);
        if (a.pos < p->cruise) {
            @T@_forward_(p, &a, p->accel_last);
        } else if (a.pos > p->cruise) {
            @T@_backward_(p, &a);
        }
    }
    return r;
}

/* Steps in a row, from `pos` walking down to the cruise position, whose
 * period is faster than the deceleration table's fastest (at least 1). */
static uint32_t @T@_capped_walk_(const @T@_t *p, uint32_t pos, uint32_t far)
    STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL @T@_cursor_t c;
    STEPPER_PROFILES_LOCAL uint32_t n;
    n = 0;
    c.decel = 0;
    c.pos = pos;
    @T@_place_cursor_(p, &c);
    while (n < far && c.pos > p->cruise && @T@_cperiod_(&c) < p->decel_fastest) {
        n++;
        @T@_backward_(p, &c);
    }
    return n > 0 ? n : 1;
}

"#;

/// `_init`, after the planner it starts: the tables' lengths in steps,
/// the deceleration table's fastest period (its whole expansion) and the
/// first acceleration step faster than it.
pub(super) const INIT: &str = r#"void @T@_init(@T@_t *p, const @S@uint16_t (*accel)[5], uint16_t accel_runs,
    const @S@uint16_t (*decel)[5], uint16_t decel_runs) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL @T@_cursor_t c;
    STEPPER_PROFILES_LOCAL const @S@uint16_t *r;
    STEPPER_PROFILES_LOCAL uint32_t steps, interval, add, x, fastest, slack;
    STEPPER_PROFILES_LOCAL uint16_t e, count, k, frac;
    STEPPER_PROFILES_LOCAL unsigned char seen;
    fastest = 0;
    slack = 0;
    frac = 0x8000u;
    seen = 0;
    p->accel = accel;
    p->decel = decel;
    p->accel_runs = accel_runs;
    p->decel_runs = decel_runs;
    for (steps = 0, e = 0; e < accel_runs; e++) {
        count = @R@(accel[e]);
        steps = steps + count < steps ? 0xFFFFFFFFul : steps + count;
    }
    p->accel_last = steps > 0 ? steps - 1 : 0;
    for (steps = 0, e = 0; e < decel_runs; e++) {
        r = decel[e];
        count = @R@(r);
        interval = @T@_word32_(r + 1);
        add = @T@_word32_(r + 3);
        steps = steps + count < steps ? 0xFFFFFFFFul : steps + count;
        for (k = 0; k < count; k++) {
            x = frac + interval;
            frac = (uint16_t)x;
            interval += add;
            if (seen && (x >> 16) > fastest && (x >> 16) - fastest > slack) {
                slack = (x >> 16) - fastest;
            }
            if (!seen || (x >> 16) < fastest) {
                fastest = x >> 16;
                seen = 1;
            }
        }
    }
    p->decel_last = steps > 0 ? steps - 1 : 0;
    p->decel_fastest = fastest;
    p->decel_slack = slack;
    p->cap = 0xFFFFFFFFul;
    c.decel = 0;
    c.pos = 0;
    if (@T@_at_(p, &c)) {
        for (;;) {
            if (@T@_cperiod_(&c) < fastest) {
                p->cap = c.pos;
                break;
            }
            if (!@T@_forward_(p, &c, p->accel_last)) {
                break;
            }
        }
    }
    p->cruise = p->accel_last;
    c.pos = 0;
    p->empty = (unsigned char)!@T@_at_(p, &c);
    c.decel = 1;
    c.pos = 0;
    if (!p->empty) {
        p->empty = (unsigned char)!@T@_at_(p, &c);
    }
    p->len = 0;
    @T@_follow_(p, 0);
}

"#;
