/* Where a stretch starts, noted in its interval until the plan is made:
 * `_settle_` finds the state it plays from then, so that the search for it
 * runs below the planner's call, not below the planner's own calls. */
static void tpl_place_(tpl_t *p, tpl_stretch_t *s, uint32_t pos) STEPPER_PROFILES_REENTRANT
{
    (void)p;
    s->interval = pos;
}

/* The state a stretch starting at step `pos` plays its first run from: its
 * first step's remainder and interval forwards; backwards the complement of
 * the remainder after it and `-add`; held, its period with no remainder. */
static void tpl_locate_(tpl_t *p, tpl_stretch_t *s, uint32_t pos) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL tpl_cursor_t c;
    STEPPER_PROFILES_LOCAL uint32_t n;
    c.decel = s->decel;
    c.pos = pos;
    tpl_place_cursor_(p, &c);
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
        s->interval = tpl_cperiod_(&c) << 16;
        s->add = 0;
    }
    if (n > s->total) {
        n = s->total;
    }
    s->first = n > 0xFFFFu ? 0xFFFFu : (uint16_t)n;
}

/* The state every stretch of the plan plays from, once the plan is made. */
static void tpl_settle_(tpl_t *p) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL unsigned char i;
    for (i = 0; i < p->len; i++) {
        tpl_locate_(p, &p->plan[i], p->plan[i].interval);
    }
}

/* The step path enters stretch `s`, from the state planned for it. */
static void tpl_enter_(tpl_t *p, const tpl_stretch_t *s) STEPPER_PROFILES_REENTRANT
{
    p->interval = s->interval;
    p->add = s->add;
    p->frac = s->frac;
    p->run = s->run;
}

/* Steps of stretch `s` the step path takes first. */
static uint16_t tpl_first_(const tpl_stretch_t *s) STEPPER_PROFILES_REENTRANT
{
    return s->first;
}

/* The period of the step played last, from the step path's state: the
 * interval before the last addition and the remainder after it. */
static uint32_t tpl_last_(const tpl_t *p) STEPPER_PROFILES_REENTRANT
{
    return (p->interval - p->add - p->frac + 0xFFFFul) >> 16;
}

/* The first of the last `r` steps at which the deceleration table, read at
 * the steps that remain, is not faster than the acceleration side walking
 * from `pos` towards the cruise position; `r` if none is. */
static uint32_t tpl_crossing_(const tpl_t *p, uint32_t pos, uint32_t r)
    STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL tpl_cursor_t d, a;
    STEPPER_PROFILES_LOCAL uint32_t j;
    d.decel = 1;
    d.pos = r - 1;
    tpl_place_cursor_(p, &d);
    a.decel = 0;
    a.pos = pos;
    tpl_place_cursor_(p, &a);
    for (j = 0; j < r; j++) {
        if (tpl_cperiod_(&d) >= tpl_cperiod_(&a)) {
            return j;
        }
        tpl_backward_(p, &d);
        if (a.pos < p->cruise) {
            tpl_forward_(p, &a, p->accel_last);
        } else if (a.pos > p->cruise) {
            tpl_backward_(p, &a);
        }
    }
    return r;
}

/* Steps in a row, from `pos` walking down to the cruise position, whose
 * period is faster than the deceleration table's fastest (at least 1). */
static uint32_t tpl_capped_walk_(const tpl_t *p, uint32_t pos, uint32_t far)
    STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL tpl_cursor_t c;
    STEPPER_PROFILES_LOCAL uint32_t n;
    n = 0;
    c.decel = 0;
    c.pos = pos;
    tpl_place_cursor_(p, &c);
    while (n < far && c.pos > p->cruise && tpl_cperiod_(&c) < p->decel_fastest) {
        n++;
        tpl_backward_(p, &c);
    }
    return n > 0 ? n : 1;
}

/* The steps of a table of `n` runs (saturated at 2^32 - 1), its fastest
 * period (in `*fastest`) and its slack (in `*slack`: the most a step's period
 * is above any period before it), expanded as the step path plays it. */
static uint32_t tpl_scan_(const TPL_STORAGE uint16_t (*runs)[5], uint16_t n,
    uint32_t *fastest, uint32_t *slack) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL const TPL_STORAGE uint16_t *r;
    STEPPER_PROFILES_LOCAL uint32_t steps, interval, add, x;
    STEPPER_PROFILES_LOCAL uint16_t e, count, k, frac;
    STEPPER_PROFILES_LOCAL unsigned char seen;
    *fastest = 0;
    *slack = 0;
    frac = 0x8000u;
    seen = 0;
    for (steps = 0, e = 0; e < n; e++) {
        r = runs[e];
        count = TPL_READ(r);
        interval = tpl_word32_(r + 1);
        add = tpl_word32_(r + 3);
        steps = steps + count < steps ? 0xFFFFFFFFul : steps + count;
        for (k = 0; k < count; k++) {
            x = frac + interval;
            frac = (uint16_t)x;
            interval += add;
            if (seen && (x >> 16) > *fastest && (x >> 16) - *fastest > *slack) {
                *slack = (x >> 16) - *fastest;
            }
            if (!seen || (x >> 16) < *fastest) {
                *fastest = x >> 16;
                seen = 1;
            }
        }
    }
    return steps;
}

/* The acceleration table's slack, for the searches that keep a cruise out of
 * bands: read only when the player is given bands. */
static uint32_t tpl_accel_slack_(const tpl_t *p) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t fastest, slack;
    (void)tpl_scan_(p->accel, p->accel_runs, &fastest, &slack);
    return slack;
}
