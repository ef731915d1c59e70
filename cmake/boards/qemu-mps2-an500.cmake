# Cortex-M7 with double-precision FPU: the core of the MIMXRT1060-EVKB.
set(FACET_CPU_FLAGS -mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard)
set(FACET_LINKER_SCRIPT ${CMAKE_SOURCE_DIR}/linker/qemu-mps2-an500.ld)
set(FACET_QEMU_MACHINE mps2-an500)
