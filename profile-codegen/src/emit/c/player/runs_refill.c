/* Two words of a run as one 32-bit value, high word first; one read per
 * statement, whatever the read macro does. */
STEPPER_PROFILES_INLINE uint32_t tpl_word32_(const TPL_STORAGE uint16_t *w) STEPPER_PROFILES_REENTRANT
{
    uint32_t high = TPL_READ(w);
    return (high << 16) | TPL_READ(w + 1);
}

/* Hands the step path `n` steps, at most 255 at once; the rest later. */
STEPPER_PROFILES_INLINE unsigned char tpl_pieces_(tpl_t *p, uint16_t n)
    STEPPER_PROFILES_REENTRANT
{
    p->left = (unsigned char)(n > 255 ? 255 : n);
    p->rest = (uint16_t)(n - p->left);
    return 1;
}

/* At most `n` steps of stretch `s`, taken from its count. */
STEPPER_PROFILES_INLINE uint16_t tpl_count_down_(tpl_stretch_t *s, uint16_t n)
    STEPPER_PROFILES_REENTRANT
{
    if (s->count_hi == 0 && n > s->count_lo) {
        n = s->count_lo;
    }
    if (n > s->count_lo) {
        s->count_hi--;
    }
    s->count_lo = (uint16_t)(s->count_lo - n);
    return n;
}

/* The step path enters the next stretch with steps, from the state planned
 * for it; 0 when the plan is played. */
STEPPER_PROFILES_NOINLINE static unsigned char tpl_next_stretch_(tpl_t *p)
    STEPPER_PROFILES_REENTRANT
{
    tpl_stretch_t *s = p->cur;
    do {
        if (++s >= p->end) {
            return 0;
        }
    } while ((s->count_hi | s->count_lo) == 0);
    p->cur = s;
    p->interval = s->interval;
    p->add = s->add;
    p->frac = s->frac;
    p->run = s->run;
    return tpl_pieces_(p, tpl_count_down_(s, s->first));
}

/* The step path enters the run before its run, backwards: from its last
 * step, whose interval is interval + (count - 1) * add, with -add. On SDCC's
 * 8051 port the product is shifts and additions: its library multiplies
 * longs through an operand in static memory, which the step interrupt would
 * overwrite under a multiplication it interrupts. */
STEPPER_PROFILES_NOINLINE static unsigned char tpl_backwards_(tpl_t *p)
    STEPPER_PROFILES_REENTRANT
{
    const TPL_STORAGE uint16_t *r = p->run;
    uint32_t interval, add;
    uint16_t n, m;
    do {
        r -= 5;
        n = TPL_READ(r);
    } while (n == 0);
    p->run = r;
    interval = tpl_word32_(r + 1);
    add = tpl_word32_(r + 3);
    p->add = 0 - add;
    m = (uint16_t)(n - 1u);
#if defined(__SDCC_mcs51)
    for (; m != 0; m >>= 1, add <<= 1) {
        if (m & 1u) {
            interval += add;
        }
    }
#else
    interval += m * add;
#endif
    p->interval = interval;
    return tpl_pieces_(p, tpl_count_down_(p->cur, n));
}

/* The step path's refill. Most often the next run forwards: its five words
 * read, 16-bit counts. */
unsigned char tpl_refill_(tpl_t *p) STEPPER_PROFILES_REENTRANT
{
    const TPL_STORAGE uint16_t *r;
    uint16_t n = p->rest;
    signed char dir;
    if (n != 0) {
        return tpl_pieces_(p, n);
    }
    if ((p->cur->count_hi | p->cur->count_lo) == 0) {
        return tpl_next_stretch_(p);
    }
    dir = p->cur->dir;
    if (dir < 0) {
        return tpl_backwards_(p);
    }
    if (dir == 0) {
        /* Held: the same period again. */
        return tpl_pieces_(p, tpl_count_down_(p->cur, 0xFFFFu));
    }
    r = p->run;
    do {
        r += 5;
        n = TPL_READ(r);
    } while (n == 0);
    p->run = r;
    tpl_pieces_(p, tpl_count_down_(p->cur, n));
    p->interval = tpl_word32_(r + 1);
    p->add = tpl_word32_(r + 3);
    return 1;
}

