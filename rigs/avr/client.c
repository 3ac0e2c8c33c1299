/* An ATmega328P that plays moves from the header's C player on its Timer1,
 * the step pin traced by simavr.
 *
 * Built twice against ramps.h (written from ramps.toml with
 * `--attribute PROGMEM`): with RUNS=0 it plays the 400-entry per-step table
 * STEPS_PERIODS with ramps_player_*, with RUNS=1 the compressed
 * RUNS_RUNS with ramps_runs_player_*. It plays the moves MOVES lists,
 * `{steps, stop_at, dir}` each (a stop once `stop_at` steps are played,
 * none when 0; the direction pin PD7's level), as the driver (src/main.rs)
 * defines it; then, the timer off, it
 * plans the first move again and stops it 60 steps in, for the harness to
 * count that stop's cycles; then it sleeps with interrupts off, which ends
 * simavr.
 *
 * Why every edge of the step pin is exact to the cycle:
 *
 * - Timer1 runs in CTC mode (WGM12): TCNT1 counts from 0 to OCR1A, and on
 *   the clock after TCNT1 == OCR1A it restarts from 0. An interval is
 *   OCR1A + 1 timer ticks, so a period of p ticks is OCR1A = p - 1.
 * - OC1A toggles on each compare match (COM1A0), in hardware: every period
 *   is one edge of the pin (a driver that steps on both edges, as TMC's
 *   `dedge` does, takes a step per edge). The interrupt's latency never
 *   moves an edge.
 * - In CTC mode OCR1A is not double-buffered: the value written takes
 *   effect at once, for the interval running. The compare match that ends
 *   interval k starts interval k + 1 and raises the interrupt, which writes
 *   period k + 1. It lands in time as long as the interrupt writes OCR1A
 *   before TCNT1 gets there, that is before the period elapses: the shortest
 *   period here is 1000 CPU cycles (16 kHz at clk/8), the interrupt at most
 *   about 500 (a run's refill), 90 to 140 on average.
 * - The first period is written before the clock starts: TCNT1 = 0,
 *   OCR1A = p0 - 1, then the write of TCCR1B that selects the clock starts
 *   interval 0; simavr counts from that write. On the part, clk/8 comes from
 *   a prescaler that runs freely: it is reset just before (GTCCR's
 *   PSRSYNC), so that the first tick comes a whole prescaler period after
 *   it, as every later one does.
 * - The direction pin (PD7; not PD2, INT0, whose low level wakes the
 *   sleeping core in simavr and would stamp edges a cycle early) is set
 *   before the clock starts, so that a reversal's first step comes a whole
 *   first period after it: at least the driver's `dir_setup`
 *   (NAME_DIR_SETUP_TICKS), which the profile's check keeps the first entry
 *   no shorter than. No wait is needed.

 * The CPU sleeps (idle) between interrupts, so that every compare match
 * comes while it sleeps: simavr stamps a pin's change at the end of the
 * instruction under way (and wakes a sleeping core one cycle after the timer's
 * event), so a match during an instruction would be stamped up to 3 cycles
 * late; asleep, every stamp is the match's cycle plus that one. */

#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>
#include <avr/avr_mcu_section.h> /* simavr's, -I/usr/include/simavr */

#define STEPPER_PROFILES_RAMPS_IMPLEMENTATION
#include "ramps.h"

AVR_MCU(F_CPU, "atmega328p");
#if RUNS
AVR_MCU_VCD_FILE("runs.vcd", 1000);
#else
AVR_MCU_VCD_FILE("steps.vcd", 1000);
#endif
/* The step and direction pins, and the writes of TCCR1B that start and stop
 * each move. */
AVR_MCU_VCD_PORT_PIN('B', 1, "OC1A");
AVR_MCU_VCD_PORT_PIN('D', 7, "DIR");
const struct avr_mmcu_vcd_trace_t clock_trace[] _MMCU_ = {
    { AVR_MCU_VCD_SYMBOL("TCCR1B"), .what = (void *)&TCCR1B, },
};

#if RUNS
/* Timer1 at clk/8: 2 MHz, RUNS_TIMER_HZ. */
#define CLOCK ((1 << WGM12) | (1 << CS11))
typedef ramps_runs_player_t player_t;
#define player_start ramps_runs_player_start
#define player_stop ramps_runs_player_stop
#define player_next ramps_runs_player_next
#define player_step ramps_runs_player_step
#define player_remaining ramps_runs_player_remaining
#else
/* Timer1 at the CPU clock: 16 MHz, STEPS_TIMER_HZ. */
#define CLOCK ((1 << WGM12) | (1 << CS10))
typedef ramps_player_t player_t;
#define player_start ramps_player_start
#define player_stop ramps_player_stop
#define player_next ramps_player_next
#define player_step ramps_player_step
#define player_remaining ramps_player_remaining
#endif

player_t player;
/* Set by main when a move starts, cleared by the interrupt when it ends. */
volatile uint8_t moving;

/* The step interrupt: the period of the interval starting now, or the clock
 * stopped at the move's last edge. */
ISR(TIMER1_COMPA_vect)
{
    uint16_t period;
    if (!player_step(&player, &period)) {
        TCCR1B = (1 << WGM12);
        moving = 0;
        return;
    }
    OCR1A = period - 1;
}

/* Plays a move of `steps` steps in direction `dir` (the level of PD7),
 * stopped once `stop_at` steps are played (never when 0). */
static void move(uint32_t steps, uint32_t stop_at, uint8_t dir)
{
    uint16_t first;
    player_start(&player, steps);
    first = player_next(&player);
    if (first == 0) {
        return;
    }
    /* The direction first: the first edge comes `first` ticks after the
     * clock starts, no sooner than the driver's dir_setup. */
    if (dir) {
        PORTD |= (1 << PD7);
    } else {
        PORTD &= (uint8_t)~(1 << PD7);
    }
    TCCR1B = (1 << WGM12);
    TCNT1 = 0;
    OCR1A = first - 1;
    TIFR1 = (1 << OCF1A);
    moving = 1;
    GTCCR = (1 << PSRSYNC);
    TCCR1B = CLOCK;
    /* Sleep until each interrupt; `sei` then `sleep` lets no interrupt in
     * between, so that none is missed. */
    cli();
    while (moving) {
        sleep_enable();
        sei();
        sleep_cpu();
        sleep_disable();
        cli();
        /* Right after an interrupt, long before the next match. */
        if (stop_at != 0 && player_remaining(&player) <= steps - stop_at) {
            player_stop(&player);
            stop_at = 0;
        }
    }
    sei();
}

/* The moves to play: `steps`, the steps after which to stop (0: none), and
 * the direction. */
static const struct {
    uint32_t steps, stop_at;
    uint8_t dir;
} moves[] = { MOVES };

int main(void)
{
    uint8_t i;
    DDRB = (1 << PB1);
    DDRD = (1 << PD7);
    TCCR1A = (1 << COM1A0);
    TIMSK1 = (1 << OCIE1A);
    set_sleep_mode(SLEEP_MODE_IDLE);
#if RUNS
    ramps_runs_player_init(&player, RUNS_RUNS, RUNS_RUN_COUNT, RUNS_RUNS, RUNS_RUN_COUNT);
#else
    ramps_player_init(&player, STEPS_PERIODS, STEPS_LEN, STEPS_PERIODS, STEPS_LEN);
#endif
    sei();
    for (i = 0; i < sizeof(moves) / sizeof(moves[0]); i++) {
        move(moves[i].steps, moves[i].stop_at, moves[i].dir);
    }
    /* A stop's cost, the timer off (the harness counts it): 60 steps into
     * the first move. */
    player_start(&player, moves[0].steps);
    for (i = 0; i < 60; i++) {
        (void)player_next(&player);
    }
    player_stop(&player);
    cli();
    sleep_cpu();
    return 0;
}
