/* Runs an AVR ELF in simavr (libsimavr) and counts cycles, one instruction
 * at a time, without touching the firmware.
 *
 *   sim FIRMWARE.elf MAX_CYCLES [FUNCTION...]
 *
 * The firmware's VCD trace is written as its .mmcu section asks. On stdout,
 * one line per Timer1 compare-A interrupt:
 *
 *   isr MATCH VECTOR EPILOGUE END
 *
 * the cycles of the compare match (Timer1's last overflow, which in CTC mode
 * is the match), of the vector's first instruction, of the first
 * instruction of the interrupt's epilogue (the `pop`s and `out SREG` before
 * `reti`) and after `reti`; and one line per call of each FUNCTION named:
 *
 *   call NAME ENTRY RETURN
 *
 * simavr charges no cycle for the interrupt response (the hardware's 4, for
 * pushing the return address): these are simavr's counts. Exits with 0 when
 * the firmware sleeps with interrupts off, 1 at MAX_CYCLES. */

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <simavr/avr_timer.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_elf.h>

/* The ATmega328P's TIMER1_COMPA vector. */
#define TIMER1_COMPA 11
#define MAX_FUNCTIONS 8
#define MAX_TRACE 4096

/* simavr sleeps in real time; the cycles are what count here. */
static void no_sleep(avr_t *avr, avr_cycle_count_t how_long)
{
    (void)avr;
    (void)how_long;
}

static uint16_t opcode(const avr_t *avr, avr_flashaddr_t pc)
{
    return (uint16_t)(avr->flash[pc] | (avr->flash[pc + 1] << 8));
}

static uint16_t sp(const avr_t *avr)
{
    return (uint16_t)(avr->data[R_SPL] | (avr->data[R_SPH] << 8));
}

/* `pop rN` or `out SREG, rN`: the epilogue's instructions. */
static int epilogue(uint16_t op)
{
    return (op & 0xFE0F) == 0x900F || (op & 0xFE0F) == 0xBE0F;
}

static avr_timer_t *timer1(avr_t *avr)
{
    avr_io_t *io;
    for (io = avr->io_port; io; io = io->next) {
        if (io->kind && !strcmp(io->kind, "timer") && ((avr_timer_t *)io)->name == '1') {
            return (avr_timer_t *)io;
        }
    }
    return NULL;
}

int main(int argc, char **argv)
{
    elf_firmware_t f;
    avr_t *avr;
    avr_timer_t *t1;
    uint64_t limit;
    uint32_t fn_addr[MAX_FUNCTIONS];
    const char *fn_name[MAX_FUNCTIONS];
    int fn_count = 0, i, in_isr = 0, call = -1, trace_len = 0;
    uint16_t call_sp = 0;
    uint64_t call_entry = 0, match = 0, vector = 0;
    avr_flashaddr_t trace_pc[MAX_TRACE];
    uint64_t trace_cycle[MAX_TRACE];
    avr_flashaddr_t vector_pc;

    if (argc < 3) {
        fprintf(stderr, "usage: %s FIRMWARE.elf MAX_CYCLES [FUNCTION...]\n", argv[0]);
        return 2;
    }
    memset(&f, 0, sizeof(f));
    if (elf_read_firmware(argv[1], &f) != 0) {
        fprintf(stderr, "cannot read %s\n", argv[1]);
        return 2;
    }
    limit = strtoull(argv[2], NULL, 10);
    for (i = 3; i < argc && fn_count < MAX_FUNCTIONS; i++) {
        uint32_t s;
        for (s = 0; s < f.symbolcount; s++) {
            if (!strcmp(f.symbol[s]->symbol, argv[i])) {
                fn_addr[fn_count] = f.symbol[s]->addr;
                fn_name[fn_count] = argv[i];
                fn_count++;
                break;
            }
        }
        if (s == f.symbolcount) {
            fprintf(stderr, "no function %s in %s\n", argv[i], argv[1]);
            return 2;
        }
    }
    avr = avr_make_mcu_by_name(f.mmcu);
    if (!avr) {
        fprintf(stderr, "unknown part %s\n", f.mmcu);
        return 2;
    }
    avr_init(avr);
    avr_load_firmware(avr, &f);
    avr->sleep = no_sleep;
    t1 = timer1(avr);
    if (!t1) {
        fprintf(stderr, "no Timer1\n");
        return 2;
    }
    vector_pc = TIMER1_COMPA * avr->vector_size;

    for (;;) {
        avr_flashaddr_t pc = avr->pc;
        uint64_t before = avr->cycle;
        int running = avr->state == cpu_Running;
        int state;
        uint16_t op = opcode(avr, pc);
        if (in_isr && running && trace_len < MAX_TRACE) {
            trace_pc[trace_len] = pc;
            trace_cycle[trace_len] = before;
            trace_len++;
        }
        state = avr_run(avr);
        if (state == cpu_Done) {
            avr_terminate(avr);
            return 0;
        }
        if (state == cpu_Crashed || avr->cycle > limit) {
            fprintf(stderr, "stopped at cycle %llu (state %d)\n",
                (unsigned long long)avr->cycle, state);
            avr_terminate(avr);
            return 1;
        }
        if (in_isr && running && op == 0x9518) {
            /* reti: back from the interrupt; its epilogue is the run of
             * pops and `out SREG` before it. */
            int k = trace_len - 1;
            while (k > 0 && epilogue(opcode(avr, trace_pc[k - 1]))) {
                k--;
            }
            printf("isr %llu %llu %llu %llu\n", (unsigned long long)match,
                (unsigned long long)vector, (unsigned long long)trace_cycle[k],
                (unsigned long long)avr->cycle);
            in_isr = 0;
        }
        if (!in_isr && avr->pc == vector_pc) {
            in_isr = 1;
            trace_len = 0;
            match = t1->tov_base;
            vector = avr->cycle;
        }
        if (call >= 0 && !in_isr && sp(avr) > call_sp) {
            printf("call %s %llu %llu\n", fn_name[call], (unsigned long long)call_entry,
                (unsigned long long)avr->cycle);
            call = -1;
        }
        if (call < 0 && !in_isr) {
            for (i = 0; i < fn_count; i++) {
                if (avr->pc == fn_addr[i]) {
                    call = i;
                    call_sp = sp(avr);
                    call_entry = avr->cycle;
                }
            }
        }
    }
}
