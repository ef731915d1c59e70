# ARM926EJ-S, ARM state, soft-float: the ARMv5 handheld class of the paper's PDA.
set(FACET_CPU_FLAGS -mcpu=arm926ej-s -marm -mfloat-abi=soft)
set(FACET_LINKER_SCRIPT ${CMAKE_SOURCE_DIR}/linker/qemu-versatilepb.ld)
set(FACET_QEMU_MACHINE versatilepb)
