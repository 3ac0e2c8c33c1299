void tpl_init(tpl_t *p, const TPL_STORAGE TPL_WORD *accel, uint32_t accel_len,
    const TPL_STORAGE TPL_WORD *decel, uint32_t decel_len) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t i, fastest;
    p->accel = accel;
    p->decel = decel;
    p->accel_len = accel_len;
    p->decel_len = decel_len;
    p->accel_last = accel_len > 0 ? accel_len - 1 : 0;
    p->decel_last = decel_len > 0 ? decel_len - 1 : 0;
    p->decel_slack = tpl_slack_(decel, decel_len, &fastest);
    p->decel_fastest = fastest;
    p->accel_slack = 0;
    p->avoid = 0;
    p->avoid_count = 0;
    p->cap = 0xFFFFFFFFul;
    for (i = 0; i < accel_len; i++) {
        if ((uint32_t)TPL_READ(accel + i) < fastest) {
            p->cap = i;
            break;
        }
    }
    p->cruise = p->accel_last;
    p->empty = (unsigned char)(accel_len == 0 || decel_len == 0);
    p->len = 0;
    tpl_follow_(p, 0);
}

