/* One step of the acceleration side towards the cruise position: 1, -1 or 0. */
static signed char tpl_toward_(const tpl_t *p, uint32_t pos) STEPPER_PROFILES_REENTRANT
{
    return pos < p->cruise ? 1 : pos > p->cruise ? -1 : 0;
}

/* Adds a stretch to the plan (at most 8: a capped walk, a walk and a cruise
 * out of reach of the deceleration table, then a walk, a cruise and the
 * deceleration within reach). */
static void tpl_push_(tpl_t *p, unsigned char decel, uint32_t pos, signed char dir,
    uint32_t count, uint32_t acc, signed char acc_dir) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL tpl_stretch_t *s;
    if (p->len >= 8) {
        return;
    }
    s = &p->plan[p->len];
    p->len++;
    s->count_hi = (uint16_t)(count >> 16);
    s->count_lo = (uint16_t)count;
    s->total = count;
    s->acc = acc;
    s->acc_dir = acc_dir;
    s->dir = dir;
    s->decel = decel;
    s->decelerating = (unsigned char)(decel && dir < 0);
    tpl_place_(p, s, pos);
}

/* The acceleration side walking from `pos` for `n` steps (towards the cruise
 * position, reaching it at most), then holding; where it ends. */
static uint32_t tpl_walk_(tpl_t *p, uint32_t pos, uint32_t n) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t distance, walked;
    STEPPER_PROFILES_LOCAL signed char dir;
    distance = pos > p->cruise ? pos - p->cruise : p->cruise - pos;
    walked = n < distance ? n : distance;
    dir = tpl_toward_(p, pos);
    if (walked > 0) {
        tpl_push_(p, 0, pos, dir, walked, pos, dir);
    }
    pos = dir > 0 ? pos + walked : pos - walked;
    if (n > walked) {
        tpl_push_(p, 0, pos, 0, n - walked, pos, 0);
    }
    return pos;
}

/* Plans `r` steps of a move that is not decelerating, the acceleration side
 * at `pos`: the stretches it is made of. The last steps, the deceleration
 * table within reach: the acceleration side plays until the deceleration
 * table, read at the steps that remain, is not faster; then the deceleration
 * table plays to the end. */
static void tpl_plan_(tpl_t *p, uint32_t pos, uint32_t r) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t l, far, n, cap, j;
    STEPPER_PROFILES_LOCAL signed char acc_dir;
    l = p->decel_last;
    p->len = 0;
    while (r > 0 && r - 1 > l) {
        /* The deceleration table is out of reach for `far` more steps. */
        far = r - (l + 1);
        if (tpl_period_(p, 0, pos) < p->decel_fastest) {
            /* No faster than the deceleration table's fastest entry: its top
             * plays; the acceleration side only walks down. */
            acc_dir = (signed char)(p->cruise < pos ? -1 : 0);
            n = acc_dir < 0 ? tpl_capped_walk_(p, pos, far) : far;
            tpl_push_(p, 1, l, 0, n, pos, acc_dir);
            if (acc_dir < 0) {
                pos -= n;
            }
        } else if (pos < p->cruise) {
            /* Up to the cruise position or the first capped step. */
            cap = p->cap > pos ? p->cap - pos : 0;
            n = p->cruise - pos < far ? p->cruise - pos : far;
            if (cap < 1) {
                cap = 1;
            }
            if (cap < n) {
                n = cap;
            }
            pos = tpl_walk_(p, pos, n);
        } else {
            pos = tpl_walk_(p, pos, far);
            n = far;
        }
        r -= n;
    }
    if (r > 0) {
        j = tpl_crossing_(p, pos, r);
        pos = tpl_walk_(p, pos, j);
        if (j < r) {
            n = r - 1 - j;
            tpl_push_(p, 1, n, -1, n + 1, pos, 0);
        }
    }
}

/* Steps of a stretch not yet handed to the step path. */
static uint32_t tpl_count_(const tpl_stretch_t *s) STEPPER_PROFILES_REENTRANT
{
    return ((uint32_t)s->count_hi << 16) | s->count_lo;
}

/* Hands `n` steps of stretch `s` to the step path: at most 255 at once. */
static void tpl_take_(tpl_t *p, tpl_stretch_t *s, uint16_t n) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t count;
    count = tpl_count_(s) - n;
    s->count_hi = (uint16_t)(count >> 16);
    s->count_lo = (uint16_t)count;
    p->left = (unsigned char)(n > 255 ? 255 : n);
    p->rest = (uint16_t)(n - p->left);
}

/* Follows the plan from its start: its first steps taken at once. */
static void tpl_follow_(tpl_t *p, uint32_t before) STEPPER_PROFILES_REENTRANT
{
    p->before = before;
    tpl_settle_(p);
    p->cur = p->plan;
    p->end = p->plan + p->len;
    p->left = 0;
    p->rest = 0;
    if (p->len == 0) {
        p->plan[0].count_hi = 0;
        p->plan[0].count_lo = 0;
    } else {
        tpl_enter_(p, p->plan);
        tpl_take_(p, p->plan, tpl_first_(p->plan));
    }
}

uint32_t tpl_remaining(const tpl_t *p) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t n;
    STEPPER_PROFILES_LOCAL unsigned char i;
    n = (uint32_t)p->left + p->rest;
    for (i = 0; i < p->len; i++) {
        n += tpl_count_(&p->plan[i]);
    }
    return n;
}

/* Steps of the stretch being played that have been played. */
static uint32_t tpl_played_(const tpl_t *p) STEPPER_PROFILES_REENTRANT
{
    return p->cur->total - tpl_count_(p->cur) - p->rest - p->left;
}

/* Where the acceleration side stands after the steps played, and whether the
 * deceleration table has taken over. */
static uint32_t tpl_acc_(const tpl_t *p, unsigned char *decelerating)
    STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL const tpl_stretch_t *s;
    STEPPER_PROFILES_LOCAL uint32_t played;
    s = p->cur;
    *decelerating = 0;
    if (s >= p->end) {
        return 0;
    }
    played = tpl_played_(p);
    *decelerating = s->decelerating;
    return s->acc_dir > 0 ? s->acc + played : s->acc_dir < 0 ? s->acc - played : s->acc;
}

/* The period of the last step played, in ticks (0 at rest). Nothing of a plan
 * is played only right after it is made: then the period played before. */
static uint32_t tpl_last_period_(const tpl_t *p) STEPPER_PROFILES_REENTRANT
{
    if (p->cur >= p->end || tpl_played_(p) == 0) {
        return p->before;
    }
    return tpl_last_(p);
}

/* The last position of the deceleration table (`decel`) or the acceleration
 * table whose period is not shorter than `current` (0 when none is), as a
 * walk down from the table's last position finds it: a bisection for `k`
 * steps below the last short by more than the table's slack (a step's period
 * is at most that above any period before it, so every step above is short
 * too), then a walk down from there. */
static uint32_t tpl_last_at_least_(const tpl_t *p, unsigned char decel, uint32_t current)
    STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t lo, hi, mid, pos, t, last, slack;
    last = decel ? p->decel_last : p->accel_last;
    slack = decel ? p->decel_slack : p->accel_slack;
    lo = 0;
    hi = last + 1;
    while (lo < hi) {
        mid = lo + ((hi - lo) >> 1);
        t = tpl_period_(p, decel, last - mid);
        if (t < current && current - t > slack) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    pos = lo > last ? 0 : last - lo;
    while (pos > 0 && tpl_period_(p, decel, pos) < current) {
        pos--;
    }
    return pos;
}

/* The last position of the deceleration table whose period is not shorter
 * than `current` (0 when none is). */
static uint32_t tpl_entry_point_(const tpl_t *p, uint32_t current) STEPPER_PROFILES_REENTRANT
{
    return tpl_last_at_least_(p, 1, current);
}

/* Whether step `pos` of the acceleration table lies in a band the player
 * avoids (the first that holds it); then `*longest` is that band's longest
 * period. */
static unsigned char tpl_band_(const tpl_t *p, uint32_t pos, uint32_t *longest)
    STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t t;
    STEPPER_PROFILES_LOCAL unsigned char i;
    t = tpl_period_(p, 0, pos);
    for (i = 0; i < p->avoid_count; i++) {
        if (t >= p->avoid[2 * i] && t <= p->avoid[2 * i + 1]) {
            *longest = p->avoid[2 * i + 1];
            return 1;
        }
    }
    return 0;
}

/* The cruise position instead of `pos` (at most the acceleration table's
 * last) when its entry lies in a band: the last entry not shorter than the
 * band's longest period plus one, past each band that search lands in (as
 * many times as there are bands); `pos` when outside every band, and where
 * a band reaches the longest period there is. */
static uint32_t tpl_outside_(const tpl_t *p, uint32_t pos) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t longest, ticks;
    STEPPER_PROFILES_LOCAL unsigned char i;
    if (!tpl_band_(p, pos, &longest) || longest == 0xFFFFFFFFul) {
        return pos;
    }
    ticks = longest + 1;
    for (i = 0; i < p->avoid_count; i++) {
        pos = tpl_last_at_least_(p, 0, ticks);
        if (!tpl_band_(p, pos, &longest) || longest < ticks || longest == 0xFFFFFFFFul) {
            break;
        }
        ticks = longest + 1;
    }
    return tpl_last_at_least_(p, 0, ticks);
}

void tpl_avoid(tpl_t *p, const uint32_t *bands, unsigned char count) STEPPER_PROFILES_REENTRANT
{
    p->avoid = bands;
    p->avoid_count = bands != 0 ? count : 0;
    if (p->avoid_count > 0) {
        p->accel_slack = tpl_accel_slack_(p);
    }
}

void tpl_start(tpl_t *p, uint32_t steps) STEPPER_PROFILES_REENTRANT
{
    p->cruise = p->accel_last;
    p->len = 0;
    if (steps > 0 && !p->empty) {
        tpl_plan_(p, 0, steps);
    }
    tpl_follow_(p, 0);
}

void tpl_set_cruise(tpl_t *p, uint32_t pos) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL unsigned char decelerating;
    STEPPER_PROFILES_LOCAL uint32_t acc, remaining, last;
    p->cruise = pos < p->accel_last ? pos : p->accel_last;
    if (p->avoid_count > 0 && !p->empty) {
        p->cruise = tpl_outside_(p, p->cruise);
    }
    acc = tpl_acc_(p, &decelerating);
    remaining = tpl_remaining(p);
    if (remaining > 0 && !decelerating) {
        last = tpl_last_period_(p);
        tpl_plan_(p, acc, remaining);
        tpl_follow_(p, last);
    }
}

void tpl_stop(tpl_t *p) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL unsigned char decelerating;
    STEPPER_PROFILES_LOCAL uint32_t remaining, current, needed, acc;
    remaining = tpl_remaining(p);
    if (remaining == 0) {
        return;
    }
    current = tpl_last_period_(p);
    /* Not moving yet, or already slower than the table's slowest entry: at
     * rest now. */
    if (current == 0 || tpl_period_(p, 1, 0) < current) {
        p->len = 0;
        tpl_follow_(p, current);
        return;
    }
    needed = tpl_entry_point_(p, current) + 1;
    if (needed < remaining) {
        acc = tpl_acc_(p, &decelerating);
        p->len = 0;
        tpl_push_(p, 1, needed - 1, -1, needed, acc, 0);
        tpl_follow_(p, current);
    }
}

