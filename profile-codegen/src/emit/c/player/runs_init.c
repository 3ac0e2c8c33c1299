void tpl_init(tpl_t *p, const TPL_STORAGE uint16_t (*accel)[5], uint16_t accel_runs,
    const TPL_STORAGE uint16_t (*decel)[5], uint16_t decel_runs) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL tpl_cursor_t c;
    STEPPER_PROFILES_LOCAL uint32_t steps, fastest, slack;
    STEPPER_PROFILES_LOCAL uint16_t e, count;
    p->accel = accel;
    p->decel = decel;
    p->accel_runs = accel_runs;
    p->decel_runs = decel_runs;
    for (steps = 0, e = 0; e < accel_runs; e++) {
        count = TPL_READ(accel[e]);
        steps = steps + count < steps ? 0xFFFFFFFFul : steps + count;
    }
    p->accel_last = steps > 0 ? steps - 1 : 0;
    p->accel_slack = 0;
    steps = tpl_scan_(decel, decel_runs, &fastest, &slack);
    p->decel_last = steps > 0 ? steps - 1 : 0;
    p->decel_fastest = fastest;
    p->decel_slack = slack;
    p->avoid = 0;
    p->avoid_count = 0;
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

