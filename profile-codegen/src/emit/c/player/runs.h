/* A stretch of a move: steps reading one table at positions that move the
 * same way, and the state its first run starts from. Part of tpl_t. */
typedef struct {
    uint16_t count_hi;          /* steps not yet handed to the step path: */
    uint16_t count_lo;          /* count_hi * 65536 + count_lo */
    uint32_t total;             /* steps in all */
    uint32_t acc;               /* where the acceleration side stands at its start */
    uint32_t interval;          /* its first step's interval, 16.16 */
    uint32_t add;               /* added after each step of its first run */
    uint16_t frac;              /* the edges' sub-tick remainder before it */
    uint16_t first;             /* steps of its first run */
    const TPL_STORAGE uint16_t *run;     /* the words of the run it reads first */
    signed char dir;            /* positions per step: 1, -1 or 0 */
    signed char acc_dir;        /* the acceleration side's move per step */
    unsigned char decel;        /* it reads the deceleration table */
    unsigned char decelerating; /* the deceleration table has taken over */
} tpl_stretch_t;

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
    const TPL_STORAGE uint16_t *run; /* the words of the run being played */
    tpl_stretch_t *cur;     /* the stretch being played */
    tpl_stretch_t *end;     /* past the plan's last stretch */
    unsigned char len;      /* stretches in the plan */
    tpl_stretch_t plan[8];
    uint32_t before;        /* the period played before the plan began */
    const TPL_STORAGE uint16_t (*accel)[5];
    const TPL_STORAGE uint16_t (*decel)[5];
    uint16_t accel_runs, decel_runs;
    uint32_t accel_last, decel_last, decel_fastest, decel_slack, cap, cruise;
    unsigned char empty;
    uint32_t accel_slack;   /* the acceleration table's, as decel_slack, once bands are given */
    const uint32_t *avoid;  /* the bands the cruise keeps out of, in pairs */
    unsigned char avoid_count;
} tpl_t;

/* Plays from `accel` (`accel_runs` runs) up and `decel` (`decel_runs` runs)
 * down, both ordered slow to fast; at rest. */
void tpl_init(tpl_t *p, const TPL_STORAGE uint16_t (*accel)[5], uint16_t accel_runs,
    const TPL_STORAGE uint16_t (*decel)[5], uint16_t decel_runs) STEPPER_PROFILES_REENTRANT;
/* Starts a move of `steps` steps from rest, cruising at the acceleration
 * table's top. */
void tpl_start(tpl_t *p, uint32_t steps) STEPPER_PROFILES_REENTRANT;
/* Decelerates along the deceleration table from the current speed to rest. */
void tpl_stop(tpl_t *p) STEPPER_PROFILES_REENTRANT;
/* Cruises at step `pos` of the acceleration table (clamped to it) instead of
 * its top, walking there one step per step; a step inside a band the player
 * avoids (tpl_avoid) gives way to the fastest step slower than it. */
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

/* The next run of the plan to the step path (at most 255 steps of it at
 * once); 0 when the plan is played. Called by the step path at a run's end:
 * out of line, so that a step interrupt saves for the step path only the
 * registers the call may change. */
unsigned char tpl_refill_(tpl_t *p) STEPPER_PROFILES_REENTRANT;

/* Plays the next step: writes its period, in ticks, to `*period` and returns
 * 1, or returns 0 once the move is done. A countdown and the run's additions
 * (16 bits for the remainder, 32 for the interval): no division, no
 * multiplication. At a run's end, and every 255 steps, a refill. The form a
 * step interrupt costs least with. */
STEPPER_PROFILES_INLINE unsigned char tpl_step(tpl_t *p, uint16_t *period)
    STEPPER_PROFILES_REENTRANT
{
    uint32_t interval, x;
    unsigned char left = p->left;
    if (STEPPER_PROFILES_UNLIKELY(left == 0)) {
        if (!tpl_refill_(p)) {
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
STEPPER_PROFILES_INLINE uint16_t tpl_next(tpl_t *p) STEPPER_PROFILES_REENTRANT
{
    uint16_t period;
    return tpl_step(p, &period) ? period : 0;
}

