/*
 * Instruction-count markers for tools/qemu/icount: each is exactly one return instruction in a
 * section of its own, so the plugin's count between them is exact (see icount.c).
 */
    .syntax unified
#if defined(__thumb__)
    .thumb
#define FUNC(name) .section .text.name, "ax", %progbits; .global name; .type name, %function; .thumb_func; name:
#else
    .arm
#define FUNC(name) .section .text.name, "ax", %progbits; .global name; .type name, %function; name:
#endif

FUNC(facet_mark_begin)
    bx lr
    .size facet_mark_begin, . - facet_mark_begin

FUNC(facet_mark_end)
    bx lr
    .size facet_mark_end, . - facet_mark_end

/* void facet_known_loop(uint32_t n): the calibration region of the icount test.
 * Between the markers it executes exactly 2n + 1 instructions (subs/bne n times, then the
 * bl to the end marker), for n >= 1. */
FUNC(facet_known_loop)
    push {r4, lr}
    mov r4, r0
    bl facet_mark_begin
1:  subs r4, r4, #1
    bne 1b
    bl facet_mark_end
    pop {r4, pc}
    .size facet_known_loop, . - facet_known_loop
