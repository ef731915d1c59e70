/*
 * ARM926EJ-S exception vectors and reset path for QEMU versatilepb.
 *
 * The image is linked at 0, so the vector table is the first thing in RAM. Each vector loads
 * its handler's address into pc. Reset sets up one small stack per exception mode, then runs
 * the rest of the firmware in System mode (privileged, shares the user registers), so a
 * semihosting SVC never clobbers the firmware's own lr.
 */
    .syntax unified
    .arm

    .section .vectors, "ax", %progbits
    .global _vectors
_vectors:
    ldr pc, =_reset
    ldr pc, =_undefined
    ldr pc, =_svc_unexpected
    ldr pc, =_prefetch_abort
    ldr pc, =_data_abort
    nop                         /* reserved */
    ldr pc, =_irq_unexpected
    ldr pc, =_fiq_unexpected
    .ltorg

    .section .text._reset, "ax", %progbits
    .global _reset
    .type _reset, %function
_reset:
    /* Exception stacks: 1 KiB each at the top of the stack region (see the linker script). */
    ldr r0, =__stack_end
    msr cpsr_c, #0xD7           /* Abort mode, IRQ+FIQ masked */
    mov sp, r0
    sub r0, r0, #1024
    msr cpsr_c, #0xDB           /* Undefined mode */
    mov sp, r0
    sub r0, r0, #1024
    msr cpsr_c, #0xD2           /* IRQ mode */
    mov sp, r0
    sub r0, r0, #1024
    msr cpsr_c, #0xD3           /* Supervisor mode */
    mov sp, r0
    sub r0, r0, #1024
    msr cpsr_c, #0xDF           /* System mode: the firmware runs here, interrupts masked */
    mov sp, r0
    bl board_reset              /* C++ from here on: never returns */
1:  b 1b

/* Each fault stub passes (kind, address of the faulting instruction) to board_fault. */
    .macro FAULT_STUB name, kind, lr_offset
    .section .text.\name, "ax", %progbits
    .type \name, %function
\name:
    sub r1, lr, #\lr_offset
    mov r0, #\kind
    b board_fault
    .endm

    FAULT_STUB _undefined, 0, 4
    FAULT_STUB _svc_unexpected, 1, 4
    FAULT_STUB _prefetch_abort, 2, 4
    FAULT_STUB _data_abort, 3, 8
    FAULT_STUB _irq_unexpected, 4, 4
    FAULT_STUB _fiq_unexpected, 5, 4
