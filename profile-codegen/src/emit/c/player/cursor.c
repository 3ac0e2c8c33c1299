/* A position along a table of runs (the deceleration table when `decel`):
 * its run, its step in the run, the remainder before it and its interval;
 * its run's add and count, read once (add 0 past the table). */
typedef struct {
    uint32_t pos;
    uint32_t interval;
    uint32_t add;
    uint16_t entry;
    uint16_t within;
    uint16_t frac;
    uint16_t count;
    unsigned char in_table;
    unsigned char decel;
} tpl_cursor_t;

/* The words of run `e` of the cursor's table; 0 past its end. */
static const TPL_STORAGE uint16_t *tpl_run_(const tpl_t *p, const tpl_cursor_t *c, uint16_t e)
    STEPPER_PROFILES_REENTRANT
{
    if (e >= (c->decel ? p->decel_runs : p->accel_runs)) {
        return 0;
    }
    return (c->decel ? p->decel : p->accel)[e];
}

/* The remainder `n` steps of a run later: frac + n * interval +
 * n (n - 1) / 2 * add, of which only the low 16 bits count, so 16-bit
 * products (the triangle's halved factor chosen by parity). */
static uint16_t tpl_ahead_(uint16_t frac, uint16_t interval, uint16_t add, uint16_t n)
    STEPPER_PROFILES_REENTRANT
{
    uint16_t triangle = (n & 1u) ? (uint16_t)((unsigned)n * (uint16_t)((n - 1u) >> 1))
                                 : (uint16_t)((unsigned)(n >> 1) * (uint16_t)(n - 1u));
    return (uint16_t)(frac + (unsigned)n * interval + (unsigned)triangle * add);
}

/* The cursor at step `c->pos` of its table; 0 past its end. The runs before
 * it move the remainder on: their counts and low words only. */
static unsigned char tpl_at_(const tpl_t *p, tpl_cursor_t *c) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL const TPL_STORAGE uint16_t *r;
    STEPPER_PROFILES_LOCAL uint32_t start;
    STEPPER_PROFILES_LOCAL uint16_t e, count, low, frac;
    start = 0;
    frac = 0x8000u;
    for (e = 0; (r = tpl_run_(p, c, e)) != 0; e++) {
        count = TPL_READ(r);
        if (c->pos - start < count) {
            c->count = count;
            c->interval = tpl_word32_(r + 1);
            c->add = tpl_word32_(r + 3);
            c->in_table = 1;
            c->entry = e;
            c->within = (uint16_t)(c->pos - start);
            c->frac = tpl_ahead_(frac, (uint16_t)c->interval, (uint16_t)c->add,
                c->within);
            c->interval += (uint32_t)c->within * c->add;
            return 1;
        }
        low = TPL_READ(r + 2);
        frac = tpl_ahead_(frac, low, TPL_READ(r + 4), count);
        start = start + count < start ? 0xFFFFFFFFul : start + count;
        if (start > c->pos) {
            return 0;
        }
    }
    return 0;
}

/* The period under a cursor, in ticks. */
static uint32_t tpl_cperiod_(const tpl_cursor_t *c) STEPPER_PROFILES_REENTRANT
{
    return (c->frac + c->interval) >> 16;
}

/* The cursor at step `c->pos`, or at step 0 of the first run with nothing
 * played (period 0) when there is no such step. */
static void tpl_place_cursor_(const tpl_t *p, tpl_cursor_t *c) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL const TPL_STORAGE uint16_t *r;
    if (!tpl_at_(p, c)) {
        c->pos = 0;
        c->interval = 0;
        c->entry = 0;
        c->within = 0;
        c->frac = 0;
        c->add = 0;
        c->in_table = 0;
        r = tpl_run_(p, c, 0);
        if (r != 0) {
            c->count = TPL_READ(r);
            c->add = tpl_word32_(r + 3);
            c->in_table = 1;
        }
    }
}

/* On to the first step of the next run that holds one, the remainder
 * carried. */
static void tpl_next_run_(const tpl_t *p, tpl_cursor_t *c) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL const TPL_STORAGE uint16_t *r;
    STEPPER_PROFILES_LOCAL uint16_t count;
    c->within = 0;
    for (;;) {
        c->entry++;
        r = tpl_run_(p, c, c->entry);
        if (r == 0) {
            c->add = 0;
            c->in_table = 0;
            break;
        }
        count = TPL_READ(r);
        if (count > 0) {
            c->interval = tpl_word32_(r + 1);
            c->add = tpl_word32_(r + 3);
            c->count = count;
            break;
        }
    }
}

/* One step towards the fast end, up to step `last`; 0 at `last`. */
static unsigned char tpl_forward_(const tpl_t *p, tpl_cursor_t *c, uint32_t last)
    STEPPER_PROFILES_REENTRANT
{
    if (c->pos >= last) {
        return 0;
    }
    c->pos++;
    c->within++;
    c->frac = (uint16_t)(c->frac + c->interval);
    c->interval += c->add;
    if (c->in_table && c->within >= c->count) {
        tpl_next_run_(p, c);
    }
    return 1;
}

/* One step towards the slow end: within the run, or to the last step of the
 * previous run that holds one; 0 at step 0. */
static unsigned char tpl_backward_(const tpl_t *p, tpl_cursor_t *c) STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL const TPL_STORAGE uint16_t *r;
    STEPPER_PROFILES_LOCAL uint16_t count;
    if (c->pos == 0) {
        return 0;
    }
    c->pos--;
    if (c->within > 0) {
        c->within--;
        c->interval -= c->add;
        c->frac = (uint16_t)(c->frac - c->interval);
        return 1;
    }
    while (c->entry > 0) {
        c->entry--;
        r = tpl_run_(p, c, c->entry);
        if (r == 0) {
            break;
        }
        count = TPL_READ(r);
        if (count > 0) {
            c->within = (uint16_t)(count - 1u);
            c->add = tpl_word32_(r + 3);
            c->interval = tpl_word32_(r + 1) + (uint32_t)c->within * c->add;
            c->frac = (uint16_t)(c->frac - c->interval);
            c->count = count;
            c->in_table = 1;
            break;
        }
    }
    return 1;
}

/* The period at step `pos` of a table, in ticks; 0 past its end. */
static uint32_t tpl_period_(const tpl_t *p, unsigned char decel, uint32_t pos)
    STEPPER_PROFILES_REENTRANT
{
    STEPPER_PROFILES_LOCAL tpl_cursor_t c;
    c.decel = decel;
    c.pos = pos;
    return tpl_at_(p, &c) ? tpl_cperiod_(&c) : 0;
}

