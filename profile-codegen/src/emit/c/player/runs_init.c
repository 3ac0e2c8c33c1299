void tpl_init(tpl_t *p, const TPL_STORAGE uint16_t (*accel)[5], uint16_t accel_runs,
    const TPL_STORAGE uint16_t (*decel)[5], uint16_t decel_runs) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL tpl_cursor_t c;
    STEPPER_PROFILES_LOCAL const TPL_STORAGE uint16_t *r;
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
        count = TPL_READ(accel[e]);
        steps = steps + count < steps ? 0xFFFFFFFFul : steps + count;
    }
    p->accel_last = steps > 0 ? steps - 1 : 0;
    for (steps = 0, e = 0; e < decel_runs; e++) {
        r = decel[e];
        count = TPL_READ(r);
        interval = tpl_word32_(r + 1);
        add = tpl_word32_(r + 3);
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
    if (tpl_at_(p, &c)) {
        for (;;) {
            if (tpl_cperiod_(&c) < fastest) {
                p->cap = c.pos;
                break;
            }
            if (!tpl_forward_(p, &c, p->accel_last)) {
                break;
            }
        }
    }
    p->cruise = p->accel_last;
    c.pos = 0;
    p->empty = (unsigned char)!tpl_at_(p, &c);
    c.decel = 1;
    c.pos = 0;
    if (!p->empty) {
        p->empty = (unsigned char)!tpl_at_(p, &c);
    }
    p->len = 0;
    tpl_follow_(p, 0);
}

