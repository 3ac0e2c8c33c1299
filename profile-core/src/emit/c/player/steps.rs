//! The C player of per-step tables (`NAME_PERIODS`, `uint16_t` or
//! `uint32_t`): its type, its inline step path, and what the shared planner
//! asks of it.
//!
//! `@T@` is the player's prefix (`ramps_player`), `@W@` the table's word,
//! `@S@` the storage word and a space (or nothing), `@R@` the macro that
//! reads one word of a table.

/// The type, the functions' declarations and the inline step path.
pub(super) const API: &str = r#"/* A stretch of a move: steps reading one table at entries that move the same
 * way. Part of @T@_t. */
typedef struct {
    uint16_t count_hi;          /* steps not yet handed to the step path: */
    uint16_t count_lo;          /* count_hi * 65536 + count_lo */
    uint32_t total;             /* steps in all */
    uint32_t acc;               /* where the acceleration side stands at its start */
    const @S@@W@ *first;        /* just past the entry it reads first */
    signed char dir;            /* entries per step: 1, -1 or 0 */
    signed char acc_dir;        /* the acceleration side's move per step */
    unsigned char decel;        /* it reads the deceleration table */
    unsigned char decelerating; /* the deceleration table has taken over */
} @T@_stretch_t;

/* Plays moves from an acceleration table and a deceleration table of @W@
 * periods (NAME_PERIODS, slowest first; one table for both is fine), as the
 * Rust `Player` does. Its fields are the player's own: use the functions.
 * Start, stop, change the cruise and count what remains between two steps:
 * from the step interrupt, or with it masked. */
typedef struct {
    const @S@@W@ *next;     /* just past the entry the next step reads */
    unsigned char left;     /* steps before the next refill */
    signed char step;       /* entries per step */
    uint16_t rest;          /* steps of the stretch taken, after those */
    @T@_stretch_t *cur;     /* the stretch being played */
    @T@_stretch_t *end;     /* past the plan's last stretch */
    unsigned char len;      /* stretches in the plan */
    @T@_stretch_t plan[8];
    uint32_t before;        /* the period played before the plan began */
    const @S@@W@ *accel;
    const @S@@W@ *decel;
    uint32_t accel_len, decel_len, accel_last, decel_last;
    uint32_t decel_fastest, decel_slack, cap, cruise;
    unsigned char empty;
} @T@_t;

/* Plays from `accel` (`accel_len` entries) up and `decel` (`decel_len`
 * entries) down, both ordered slow to fast; at rest. */
void @T@_init(@T@_t *p, const @S@@W@ *accel, uint32_t accel_len,
    const @S@@W@ *decel, uint32_t decel_len) STEPPER_PROFILES_REENTRANT;
/* Starts a move of `steps` steps from rest, cruising at the acceleration
 * table's top. */
void @T@_start(@T@_t *p, uint32_t steps) STEPPER_PROFILES_REENTRANT;
/* Decelerates along the deceleration table from the current speed to rest. */
void @T@_stop(@T@_t *p) STEPPER_PROFILES_REENTRANT;
/* Cruises at entry `pos` of the acceleration table (clamped to it) instead of
 * its top, walking there one entry per step. */
void @T@_set_cruise(@T@_t *p, uint32_t pos) STEPPER_PROFILES_REENTRANT;
/* Steps left in the move. */
uint32_t @T@_remaining(const @T@_t *p) STEPPER_PROFILES_REENTRANT;

/* The next steps of the plan to the step path (at most 255); 0 when the plan
 * is played. 16-bit arithmetic only. */
STEPPER_PROFILES_INLINE unsigned char @T@_refill_(@T@_t *p) STEPPER_PROFILES_REENTRANT
{
    uint16_t n = p->rest;
    if (n == 0) {
        @T@_stretch_t *s = p->cur;
        if (s->count_lo == 0 && s->count_hi == 0) {
            do {
                if (++s >= p->end) {
                    return 0;
                }
            } while (s->count_lo == 0 && s->count_hi == 0);
            p->cur = s;
            p->next = s->first;
            p->step = s->dir;
        }
        if (s->count_hi == 0) {
            n = s->count_lo;
            s->count_lo = 0;
        } else {
            /* 65535 steps of a longer stretch. */
            n = 0xFFFFu;
            if (++s->count_lo != 0) {
                s->count_hi--;
            }
        }
    }
    p->left = (unsigned char)(n > 255 ? 255 : n);
    p->rest = (uint16_t)(n - p->left);
    return 1;
}

/* Plays the next step: writes its period, in ticks, to `*period` and returns
 * 1, or returns 0 once the move is done. A countdown, a read and a pointer
 * step: no division, no multiplication, no call. Every 255 steps, and where
 * the move changes stretch (a few times a move), a refill. The form a step
 * interrupt costs least with. */
STEPPER_PROFILES_INLINE unsigned char @T@_step(@T@_t *p, @W@ *period)
    STEPPER_PROFILES_REENTRANT
{
    const @S@@W@ *at;
    unsigned char left = p->left;
    if (STEPPER_PROFILES_UNLIKELY(left == 0)) {
        if (!@T@_refill_(p)) {
            return 0;
        }
        left = p->left;
    }
    p->left = (unsigned char)(left - 1);
    at = p->next;
    p->next = at + p->step;
    *period = @R@(at - 1);
    return 1;
}

/* The period of the next step, in ticks; 0 once the move is done. */
STEPPER_PROFILES_INLINE @W@ @T@_next(@T@_t *p) STEPPER_PROFILES_REENTRANT
{
    @W@ period;
    return @T@_step(p, &period) ? period : 0;
}

"#;

/// The definitions the shared planner uses.
pub(super) const DEFINITIONS: &str = r#"/* The period at step `pos` of a table, in ticks; 0 past its end. */
static uint32_t @T@_period_(const @T@_t *p, unsigned char decel, uint32_t pos)
    STEPPER_PROFILES_REENTRANT
{
    if (decel) {
        return pos < p->decel_len ? (uint32_t)@R@(p->decel + pos) : 0;
    }
    return pos < p->accel_len ? (uint32_t)@R@(p->accel + pos) : 0;
}

/* Where a stretch starting at step `pos` reads first: just past it, so that
 * every pointer the step path makes stays within the table (a walk up never
 * reads the top entry; a move down ends just past entry 0). */
static void @T@_place_(@T@_t *p, @T@_stretch_t *s, uint32_t pos) STEPPER_PROFILES_REENTRANT
{
    s->first = (s->decel ? p->decel : p->accel) + pos + 1;
}

/* Every stretch of the plan was placed as it was pushed. */
static void @T@_settle_(@T@_t *p) STEPPER_PROFILES_REENTRANT
{
    (void)p;
}

/* The step path enters stretch `s`. */
static void @T@_enter_(@T@_t *p, const @T@_stretch_t *s) STEPPER_PROFILES_REENTRANT
{
    p->next = s->first;
    p->step = s->dir;
}

/* Steps of stretch `s` the step path takes first. */
static uint16_t @T@_first_(const @T@_stretch_t *s) STEPPER_PROFILES_REENTRANT
{
    return s->count_hi > 0 ? 0xFFFFu : s->count_lo;
}

/* The period of the step played last, when one of the stretch has been. */
static uint32_t @T@_last_(const @T@_t *p) STEPPER_PROFILES_REENTRANT
{
    return @R@(p->next - p->step - 1);
}

/* The first of the last `r` steps at which the deceleration table, read at
 * the steps that remain, is not faster than the acceleration side walking
 * from `pos` towards the cruise position; `r` if none is. */
static uint32_t @T@_crossing_(const @T@_t *p, uint32_t pos, uint32_t r)
    STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t j, d, down;
    d = r - 1;
    for (j = 0; j < r; j++) {
        if (d >= p->decel_len || pos >= p->accel_len) {
            break;
        }
        down = @R@(p->decel + d);
        if (down >= (uint32_t)@R@(p->accel + pos)) {
            return j;
        }
        d--;
        pos = pos < p->cruise ? pos + 1 : pos > p->cruise ? pos - 1 : pos;
    }
    return r;
}

/* Steps in a row, from `pos` walking down to the cruise position, whose
 * period is faster than the deceleration table's fastest (at least 1). */
static uint32_t @T@_capped_walk_(const @T@_t *p, uint32_t pos, uint32_t far)
    STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t n;
    n = 0;
    while (n < far && pos > p->cruise && @T@_period_(p, 0, pos) < p->decel_fastest) {
        n++;
        pos--;
    }
    return n > 0 ? n : 1;
}

"#;

/// `_init`, after the planner it starts.
pub(super) const INIT: &str = r#"void @T@_init(@T@_t *p, const @S@@W@ *accel, uint32_t accel_len,
    const @S@@W@ *decel, uint32_t decel_len) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t i, fastest, slack, v;
    fastest = 0;
    slack = 0;
    p->accel = accel;
    p->decel = decel;
    p->accel_len = accel_len;
    p->decel_len = decel_len;
    p->accel_last = accel_len > 0 ? accel_len - 1 : 0;
    p->decel_last = decel_len > 0 ? decel_len - 1 : 0;
    for (i = 0; i < decel_len; i++) {
        v = @R@(decel + i);
        if (i > 0 && v > fastest && v - fastest > slack) {
            slack = v - fastest;
        }
        if (i == 0 || v < fastest) {
            fastest = v;
        }
    }
    p->decel_fastest = fastest;
    p->decel_slack = slack;
    p->cap = 0xFFFFFFFFul;
    for (i = 0; i < accel_len; i++) {
        if ((uint32_t)@R@(accel + i) < fastest) {
            p->cap = i;
            break;
        }
    }
    p->cruise = p->accel_last;
    p->empty = (unsigned char)(accel_len == 0 || decel_len == 0);
    p->len = 0;
    @T@_follow_(p, 0);
}

"#;
