# Build-wide flags for the host and the ARM targets.

if(CMAKE_CROSSCOMPILING)
    set(FACET_TARGET_BUILD ON)
    if(NOT FACET_BOARD)
        message(FATAL_ERROR "FACET_BOARD is required for an ARM build (qemu-versatilepb, qemu-mps2-an500)")
    endif()
    include(${CMAKE_SOURCE_DIR}/cmake/boards/${FACET_BOARD}.cmake)

    add_compile_options(
        ${FACET_CPU_FLAGS}
        -ffunction-sections -fdata-sections
        -Wall -Wextra -Werror
        $<$<COMPILE_LANGUAGE:CXX>:-fno-exceptions>
        $<$<COMPILE_LANGUAGE:CXX>:-fno-rtti>
        $<$<COMPILE_LANGUAGE:CXX>:-fno-threadsafe-statics>
        $<$<COMPILE_LANGUAGE:CXX>:-fno-use-cxa-atexit>
        # Host and target must compute bit-identical images: no fused multiply-add.
        -ffp-contract=off)
    add_compile_definitions(FACET_TARGET=1)
    add_link_options(
        ${FACET_CPU_FLAGS}
        --specs=nano.specs
        -nostartfiles
        -Wl,--gc-sections,--print-memory-usage
        # No heap on the target: every allocator entry point is redirected to
        # boards/common/no_heap.cpp, whose section the linker script refuses.
        -Wl,--wrap=malloc,--wrap=free,--wrap=calloc,--wrap=realloc
        -Wl,--wrap=_malloc_r,--wrap=_free_r,--wrap=_calloc_r,--wrap=_realloc_r
        -Wl,--wrap=_sbrk,--wrap=_sbrk_r
        -Wl,--wrap=_Znwj,--wrap=_Znaj,--wrap=_ZnwjRKSt9nothrow_t,--wrap=_ZnajRKSt9nothrow_t)
else()
    set(FACET_TARGET_BUILD OFF)
    add_compile_options(-Wall -Wextra -Werror)
    option(FACET_SANITIZE "Build with AddressSanitizer + UndefinedBehaviorSanitizer" OFF)
    if(FACET_SANITIZE)
        add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
        add_link_options(-fsanitize=address,undefined)
    endif()
    if(FACET_FUZZ)
        # Coverage feedback from the libraries too (cdt/, geom/), not just the fuzz targets:
        # without it libFuzzer mutates blind past the harness.
        add_compile_options(-fsanitize=fuzzer-no-link)
    endif()
endif()

# facet_firmware(<name> SOURCES ...): a firmware ELF for the configured board.
function(facet_firmware name)
    cmake_parse_arguments(FW "" "" "SOURCES;LIBS" ${ARGN})
    add_executable(${name} ${FW_SOURCES})
    set_target_properties(${name} PROPERTIES SUFFIX ".elf")
    target_link_libraries(${name} PRIVATE facet_board facet_board_common ${FW_LIBS})
    target_link_options(${name} PRIVATE -T${FACET_LINKER_SCRIPT} -Wl,-Map=$<TARGET_FILE:${name}>.map)
    set_target_properties(${name} PROPERTIES LINK_DEPENDS ${FACET_LINKER_SCRIPT})
endfunction()
