void tpl_init(tpl_t *p, const TPL_STORAGE TPL_WORD *accel, uint32_t accel_len,
    const TPL_STORAGE TPL_WORD *decel, uint32_t decel_len) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL uint32_t i, fastest, slack, v;
    fastest = 0;
    slack = 0;
    p->accel = accel;
    p->decel = decel;
    p->accel_len = accel_len;
    p->decel_len = decel_len;
    p->accel_last = accel_len > 0 ? accel_len - 1 : 0;
    p->decel_last = decel_len > 0 ? decel_len - 1 : 0;
    for (i = 0; i < decel_len; i++) {
        v = TPL_READ(decel + i);
        if (i > 0 && v > fastest && v - fastest > slack) {
            slack = v - fastest;
        }
        if (i == 0 || v < fastest) {
            fastest = v;
        }
    }
    p->decel_fastest = fastest;
    p->decel_slack = slack;
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

