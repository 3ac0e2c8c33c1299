/* A stretch of a move: steps reading one table at entries that move the same
 * way. Part of tpl_t. */
typedef struct {
    uint16_t count_hi;          /* steps not yet handed to the step path: */
    uint16_t count_lo;          /* count_hi * 65536 + count_lo */
    uint32_t total;             /* steps in all */
    uint32_t acc;               /* where the acceleration side stands at its start */
    const TPL_STORAGE TPL_WORD *first;        /* just past the entry it reads first */
    signed char dir;            /* entries per step: 1, -1 or 0 */
    signed char acc_dir;        /* the acceleration side's move per step */
    unsigned char decel;        /* it reads the deceleration table */
    unsigned char decelerating; /* the deceleration table has taken over */
} tpl_stretch_t;

/* Plays moves from an acceleration table and a deceleration table of TPL_WORD
 * periods (NAME_PERIODS, slowest first; one table for both is fine), as the
 * Rust `Player` does. Its fields are the player's own: use the functions.
 * Start, stop, change the cruise and count what remains between two steps:
 * from the step interrupt, or with it masked. */
typedef struct {
    const TPL_STORAGE TPL_WORD *next;     /* just past the entry the next step reads */
    unsigned char left;     /* steps before the next refill */
    signed char step;       /* entries per step */
    uint16_t rest;          /* steps of the stretch taken, after those */
    tpl_stretch_t *cur;     /* the stretch being played */
    tpl_stretch_t *end;     /* past the plan's last stretch */
    unsigned char len;      /* stretches in the plan */
    tpl_stretch_t plan[8];
    uint32_t before;        /* the period played before the plan began */
    const TPL_STORAGE TPL_WORD *accel;
    const TPL_STORAGE TPL_WORD *decel;
    uint32_t accel_len, decel_len, accel_last, decel_last;
    uint32_t decel_fastest, decel_slack, cap, cruise;
    unsigned char empty;
    uint32_t accel_slack;   /* the acceleration table's, as decel_slack, once bands are given */
    const uint32_t *avoid;  /* the bands the cruise keeps out of, in pairs */
    unsigned char avoid_count;
} tpl_t;

/* Plays from `accel` (`accel_len` entries) up and `decel` (`decel_len`
 * entries) down, both ordered slow to fast; at rest. */
void tpl_init(tpl_t *p, const TPL_STORAGE TPL_WORD *accel, uint32_t accel_len,
    const TPL_STORAGE TPL_WORD *decel, uint32_t decel_len) STEPPER_PROFILES_REENTRANT;
/* Starts a move of `steps` steps from rest, cruising at the acceleration
 * table's top. */
void tpl_start(tpl_t *p, uint32_t steps) STEPPER_PROFILES_REENTRANT;
/* Decelerates along the deceleration table from the current speed to rest. */
void tpl_stop(tpl_t *p) STEPPER_PROFILES_REENTRANT;
/* Cruises at entry `pos` of the acceleration table (clamped to it) instead of
 * its top, walking there one entry per step; an entry inside a band the
 * player avoids (tpl_avoid) gives way to the fastest entry slower than it. */
void tpl_set_cruise(tpl_t *p, uint32_t pos) STEPPER_PROFILES_REENTRANT;
/* Keeps the cruise out of `count` bands of periods: `bands` holds them in
 * pairs, {shortest, longest} in ticks as the table holds them, inclusive (a
 * profile's `avoid` emits them as NAME_AVOID, NAME_AVOID_COUNT bands). A
 * cruise tpl_set_cruise would set inside a band is the fastest entry slower
 * than the band instead, never faster than asked (the slowest entry where
 * none is slower); moves still cross the bands as they accelerate and
 * decelerate. The array is read, not copied: keep it (in RAM or ordinary
 * const memory, not PROGMEM) while the player plays. tpl_init clears it. */
void tpl_avoid(tpl_t *p, const uint32_t *bands, unsigned char count) STEPPER_PROFILES_REENTRANT;
/* Steps left in the move. */
uint32_t tpl_remaining(const tpl_t *p) STEPPER_PROFILES_REENTRANT;

/* The next steps of the plan to the step path (at most 255); 0 when the plan
 * is played. 16-bit arithmetic only. */
STEPPER_PROFILES_INLINE unsigned char tpl_refill_(tpl_t *p) STEPPER_PROFILES_REENTRANT
{
    uint16_t n = p->rest;
    if (n == 0) {
        tpl_stretch_t *s = p->cur;
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
STEPPER_PROFILES_INLINE unsigned char tpl_step(tpl_t *p, TPL_WORD *period)
    STEPPER_PROFILES_REENTRANT
{
    const TPL_STORAGE TPL_WORD *at;
    unsigned char left = p->left;
    if (STEPPER_PROFILES_UNLIKELY(left == 0)) {
        if (!tpl_refill_(p)) {
            return 0;
        }
        left = p->left;
    }
    p->left = (unsigned char)(left - 1);
    at = p->next;
    p->next = at + p->step;
    *period = TPL_READ(at - 1);
    return 1;
}

/* The period of the next step, in ticks; 0 once the move is done. */
STEPPER_PROFILES_INLINE TPL_WORD tpl_next(tpl_t *p) STEPPER_PROFILES_REENTRANT
{
    TPL_WORD period;
    return tpl_step(p, &period) ? period : 0;
}

