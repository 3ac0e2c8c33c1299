/* The first position of the acceleration table whose period is not longer
 * than `current`, its last when none is: as the Rust player enters that table
 * where a new end is taken while the deceleration table plays. A bisection
 * past the steps longer by more than the table's slack (every step before
 * one of those is longer too), then a walk up. The slack is read from the
 * table on each call: a pass over it. */
static uint32_t tpl_first_at_most_(const tpl_t *p, uint32_t current) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t lo, hi, mid, t, slack;
    slack = tpl_accel_slack_(p);
    lo = 0;
    hi = p->accel_last;
    while (lo < hi) {
        mid = lo + ((hi - lo) >> 1);
        t = tpl_period_(p, 0, mid);
        if (t > current && t - current > slack) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    while (lo < p->accel_last && tpl_period_(p, 0, lo) > current) {
        lo++;
    }
    return lo;
}

/* Ends the move `steps` steps from now, more than remain: on from where it
 * stands along the acceleration table (entered, where the deceleration table
 * has taken over, at its first entry not longer than the current period),
 * as the Rust player's retarget does. */
static void tpl_extend_(tpl_t *p, uint32_t steps) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL unsigned char decelerating;
    STEPPER_PROFILES_LOCAL uint32_t acc, current, from;
    acc = tpl_acc_(p, &decelerating);
    current = tpl_last_period_(p);
    from = current == 0 ? 0 : decelerating ? tpl_first_at_most_(p, current) : acc;
    tpl_plan_(p, from, steps);
    tpl_follow_(p, current);
}

void tpl_axis_init(tpl_axis_t *a, int32_t position) STEPPER_PROFILES_REENTRANT
{
    a->player.len = 0;
    tpl_follow_(&a->player, 0);
    a->end = position;
    a->dir = 1;
    a->len = 0;
}

int32_t tpl_axis_position(const tpl_axis_t *a) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL int32_t left;
    left = (int32_t)tpl_remaining(&a->player);
    return a->dir > 0 ? a->end - left : a->end + left;
}

signed char tpl_axis_direction(const tpl_axis_t *a) STEPPER_PROFILES_REENTRANT
{
    return a->dir;
}

unsigned char tpl_axis_queued(const tpl_axis_t *a) STEPPER_PROFILES_REENTRANT
{
    return a->len;
}

/* Starts a move from rest to `target`, the cruise kept. */
static void tpl_axis_start_(tpl_axis_t *a, int32_t target) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL int32_t position;
    STEPPER_PROFILES_LOCAL uint32_t steps;
    position = tpl_axis_position(a);
    if (target > position) {
        a->dir = 1;
        steps = (uint32_t)(target - position);
    } else {
        steps = (uint32_t)(position - target);
        if (steps > 0) {
            a->dir = -1;
        }
    }
    a->player.len = 0;
    if (steps > 0 && !a->player.empty) {
        tpl_plan_(&a->player, 0, steps);
    }
    tpl_follow_(&a->player, 0);
    a->end = a->dir > 0 ? position + (int32_t)steps : position - (int32_t)steps;
}

unsigned char tpl_axis_queue(tpl_axis_t *a, int32_t target) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL int32_t last, before;
    STEPPER_PROFILES_LOCAL signed char into, ahead;
    if (a->len == 0 && tpl_remaining(&a->player) == 0) {
        tpl_axis_start_(a, target);
        return 1;
    }
    /* The last target, and the way the move to it goes. */
    if (a->len > 0) {
        last = a->targets[a->len - 1];
        before = a->len > 1 ? a->targets[a->len - 2] : a->end;
        into = last > before ? 1 : last < before ? -1 : 0;
    } else {
        last = a->end;
        into = a->dir;
    }
    ahead = target > last ? 1 : target < last ? -1 : 0;
    if (ahead == 0) {
        return 1;
    }
    if (ahead == into) {
        if (a->len > 0) {
            a->targets[a->len - 1] = target;
        } else {
            /* On to it at speed: the move playing ends there. */
            tpl_extend_(&a->player, (uint32_t)(ahead > 0 ? target - tpl_axis_position(a)
                                                        : tpl_axis_position(a) - target));
            a->end = target;
        }
        return 1;
    }
    if (a->len == STEPPER_PROFILES_QUEUE) {
        return 0;
    }
    a->targets[a->len++] = target;
    return 1;
}

unsigned char tpl_axis_step(tpl_axis_t *a, TPL_WORD *period) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL int32_t target;
    STEPPER_PROFILES_LOCAL unsigned char i;
    if (tpl_step(&a->player, period)) {
        return 1;
    }
    if (a->len == 0) {
        return 0;
    }
    /* The next turning point: a move from rest, the rest moved up. */
    target = a->targets[0];
    for (i = 1; i < a->len; i++) {
        a->targets[i - 1] = a->targets[i];
    }
    a->len--;
    tpl_axis_start_(a, target);
    return tpl_step(&a->player, period);
}
