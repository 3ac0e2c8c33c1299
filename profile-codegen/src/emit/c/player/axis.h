/* The most targets an axis holds after the move playing: the move after it
 * and 8 turning points beyond, as the Rust Axis::queue. */
#ifndef STEPPER_PROFILES_QUEUE
#define STEPPER_PROFILES_QUEUE 9
#endif

/* A player with a position and a queue of moves, as the Rust Axis::queue:
 * consecutive targets the same way make one move to the farthest, so the
 * motor passes the ones between at speed (the fastest that still stops at
 * the end of the queue); a target the other way waits for the move before it
 * to end at rest, then reverses. Positions are signed 32-bit steps. Its
 * fields are the axis's own: use the functions, between two steps (from the
 * step interrupt, or with it masked). */
typedef struct {
    tpl_t player;
    int32_t end;                      /* where the move playing ends */
    signed char dir;                  /* its direction: 1 or -1 */
    unsigned char len;                /* targets waiting after it */
    int32_t targets[STEPPER_PROFILES_QUEUE];       /* in order, each a reversal of the one before */
} tpl_axis_t;

/* An axis at `position`, at rest, with nothing queued, playing its player
 * `a->player`, which tpl_init has made first (its tables, and bands if any). */
void tpl_axis_init(tpl_axis_t *a, int32_t position) STEPPER_PROFILES_REENTRANT;
/* Queues a move to `target` after the ones queued before it: at rest it
 * starts it; the same way as the last, beyond it, it joins it at speed (the
 * move playing goes on to it, or the last queued target moves out to it);
 * the other way it waits for a stop at the last, then reverses. Returns 1,
 * or 0 when STEPPER_PROFILES_QUEUE targets wait already and this one reverses. */
unsigned char tpl_axis_queue(tpl_axis_t *a, int32_t target) STEPPER_PROFILES_REENTRANT;
/* The position, in steps: exact after every step. */
int32_t tpl_axis_position(const tpl_axis_t *a) STEPPER_PROFILES_REENTRANT;
/* The direction of the move playing (1 forward, -1 backward): what the
 * driver's direction pin says for the step tpl_axis_step plays. */
signed char tpl_axis_direction(const tpl_axis_t *a) STEPPER_PROFILES_REENTRANT;
/* Targets waiting after the move playing. */
unsigned char tpl_axis_queued(const tpl_axis_t *a) STEPPER_PROFILES_REENTRANT;
/* Plays the next step (tpl_step): 1 and its period in `*period`, or 0 once
 * every move is done. Where a move ends and a reversal waits, the next
 * move's first step. */
unsigned char tpl_axis_step(tpl_axis_t *a, TPL_WORD *period) STEPPER_PROFILES_REENTRANT;
