/* A player's step path is inline: a step interrupt calling it calls no
 * function, and saves only the registers it uses. Not on SDCC's 8051
 * port, whose version 4.2 inlines these functions into reentrant ones
 * wrong. */
#ifndef STEPPER_PROFILES_INLINE
#if defined(__SDCC_mcs51)
#define STEPPER_PROFILES_INLINE static
#elif defined(__GNUC__)
#define STEPPER_PROFILES_INLINE static __inline__ __attribute__((__always_inline__))
#elif defined(__STDC_VERSION__) && __STDC_VERSION__ >= 199901L
#define STEPPER_PROFILES_INLINE static inline
#else
#define STEPPER_PROFILES_INLINE static
#endif
#endif
/* A refill is the exception: laid out off the step path where the
 * compiler can be told so. */
#ifndef STEPPER_PROFILES_UNLIKELY
#if defined(__GNUC__)
#define STEPPER_PROFILES_UNLIKELY(x) __builtin_expect(!!(x), 0)
#else
#define STEPPER_PROFILES_UNLIKELY(x) (x)
#endif
#endif
/* What only the rarest refills need stays out of their way. */
#ifndef STEPPER_PROFILES_NOINLINE
#if defined(__GNUC__)
#define STEPPER_PROFILES_NOINLINE __attribute__((__noinline__))
#else
#define STEPPER_PROFILES_NOINLINE
#endif
#endif
/* SDCC's 8051 port spills registers to internal RAM, of which an 8051
 * addresses 128 bytes directly. There every function of the players is
 * reentrant, its spills on the stack only while it runs, and the
 * planner keeps its locals in fixed places off the stack (external RAM
 * with --model-large): plan one move at a time. */
#ifndef STEPPER_PROFILES_REENTRANT
#if defined(__SDCC_mcs51)
#define STEPPER_PROFILES_REENTRANT __reentrant
#else
#define STEPPER_PROFILES_REENTRANT
#endif
#endif
#ifndef STEPPER_PROFILES_LOCAL
#if defined(__SDCC_mcs51)
#define STEPPER_PROFILES_LOCAL static
#else
#define STEPPER_PROFILES_LOCAL
#endif
#endif
