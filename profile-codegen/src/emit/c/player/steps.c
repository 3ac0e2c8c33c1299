/* The period at step `pos` of a table, in ticks; 0 past its end. A read:
 * inline wherever the planner reads one. */
STEPPER_PROFILES_INLINE uint32_t tpl_period_(const tpl_t *p, unsigned char decel, uint32_t pos)
    STEPPER_PROFILES_REENTRANT
{
    if (decel) {
        return pos < p->decel_len ? (uint32_t)TPL_READ(p->decel + pos) : 0;
    }
    return pos < p->accel_len ? (uint32_t)TPL_READ(p->accel + pos) : 0;
}

/* The slack of a table of `n` periods (the most a period is above any period
 * before it); its fastest period in `*fastest`. */
static uint32_t tpl_slack_(const TPL_STORAGE TPL_WORD *t, uint32_t n, uint32_t *fastest)
    STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t i, slack, v;
    slack = 0;
    *fastest = 0;
    for (i = 0; i < n; i++) {
        v = TPL_READ(t + i);
        if (i > 0 && v > *fastest && v - *fastest > slack) {
            slack = v - *fastest;
        }
        if (i == 0 || v < *fastest) {
            *fastest = v;
        }
    }
    return slack;
}

/* The acceleration table's slack, for the searches that keep a cruise out of
 * bands: read only when the player is given bands. */
static uint32_t tpl_accel_slack_(const tpl_t *p) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t fastest;
    return tpl_slack_(p->accel, p->accel_len, &fastest);
}

/* Where a stretch starting at step `pos` reads first: just past it, so that
 * every pointer the step path makes stays within the table (a walk up never
 * reads the top entry; a move down ends just past entry 0). */
static void tpl_place_(tpl_t *p, tpl_stretch_t *s, uint32_t pos) STEPPER_PROFILES_REENTRANT
{
    s->first = (s->decel ? p->decel : p->accel) + pos + 1;
}

/* Every stretch of the plan was placed as it was pushed. */
static void tpl_settle_(tpl_t *p) STEPPER_PROFILES_REENTRANT
{
    (void)p;
}

/* The step path enters stretch `s`. */
static void tpl_enter_(tpl_t *p, const tpl_stretch_t *s) STEPPER_PROFILES_REENTRANT
{
    p->next = s->first;
    p->step = s->dir;
}

/* Steps of stretch `s` the step path takes first. */
static uint16_t tpl_first_(const tpl_stretch_t *s) STEPPER_PROFILES_REENTRANT
{
    return s->count_hi > 0 ? 0xFFFFu : s->count_lo;
}

/* The period of the step played last, when one of the stretch has been. */
static uint32_t tpl_last_(const tpl_t *p) STEPPER_PROFILES_REENTRANT
{
    return TPL_READ(p->next - p->step - 1);
}

/* The first of the last `r` steps at which the deceleration table, read at
 * the steps that remain, is not faster than the acceleration side walking
 * from `pos` towards the cruise position; `r` if none is. */
static uint32_t tpl_crossing_(const tpl_t *p, uint32_t pos, uint32_t r)
    STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t j, d, down;
    d = r - 1;
    for (j = 0; j < r; j++) {
        if (d >= p->decel_len || pos >= p->accel_len) {
            break;
        }
        down = TPL_READ(p->decel + d);
        if (down >= (uint32_t)TPL_READ(p->accel + pos)) {
            return j;
        }
        d--;
        pos = pos < p->cruise ? pos + 1 : pos > p->cruise ? pos - 1 : pos;
    }
    return r;
}

/* Steps in a row, from `pos` walking down to the cruise position, whose
 * period is faster than the deceleration table's fastest (at least 1). */
static uint32_t tpl_capped_walk_(const tpl_t *p, uint32_t pos, uint32_t far)
    STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t n;
    n = 0;
    while (n < far && pos > p->cruise && tpl_period_(p, 0, pos) < p->decel_fastest) {
        n++;
        pos--;
    }
    return n > 0 ? n : 1;
}

