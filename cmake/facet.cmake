# Build-wide flags for the host and the ARM targets.

# A size from a board description ('4M', '256K', '0x1000', '4096') as a number of bytes.
function(facet_board_bytes text out)
    string(REGEX MATCH "^([0-9A-Fa-fx]+)([KM]?)$" _ "${text}")
    if("${CMAKE_MATCH_1}" STREQUAL "")
        message(FATAL_ERROR "board.json: not a size: ${text}")
    endif()
    set(scale 1)
    if(CMAKE_MATCH_2 STREQUAL "K")
        set(scale 1024)
    elseif(CMAKE_MATCH_2 STREQUAL "M")
        set(scale 1048576)
    endif()
    math(EXPR v "${CMAKE_MATCH_1} * ${scale}")
    set(${out} ${v} PARENT_SCOPE)
endfunction()

# What a board can do, from its description's "capabilities" (boards/<board>/board.json):
# screenshots (a host takes its pictures: QEMU's runner), mouse, touch, bench (the benches
# measure on it), flash_runner (how ./facet flash writes it: "probe-drive", or null). Sets `out`
# to the value (ON/OFF for the flags, the text or "" for flash_runner).
function(facet_board_capability board capability out)
    set(json_file ${CMAKE_SOURCE_DIR}/boards/${board}/board.json)
    file(READ ${json_file} json)
    string(JSON value ERROR_VARIABLE missing GET "${json}" capabilities ${capability})
    if(missing)
        message(FATAL_ERROR "${json_file}: no capabilities.${capability}")
    endif()
    if(value STREQUAL "null")
        set(value "")
    endif()
    set(${out} ${value} PARENT_SCOPE)
endfunction()

# A value of a board's description (boards/<board>/board.json) at the keys given, or "" when it
# is absent or null: facet_board_get(qemu-versatilepb out tests budgets).
function(facet_board_get board out)
    file(READ ${CMAKE_SOURCE_DIR}/boards/${board}/board.json json)
    string(JSON value ERROR_VARIABLE missing GET "${json}" ${ARGN})
    if(missing OR value STREQUAL "null")
        set(value "")
    endif()
    set(${out} "${value}" PARENT_SCOPE)
endfunction()

# Reads boards/<board>/board.json, the board's one description, and writes what the build
# needs from it: the CPU flags, the config header the firmware sizes its buffers from
# (facet_board_config.h) and the linker script's memory map and pack region (board_memory.ld).
macro(facet_read_board board)
    set(FACET_BOARD_JSON ${CMAKE_SOURCE_DIR}/boards/${board}/board.json)
    if(NOT EXISTS ${FACET_BOARD_JSON})
        message(FATAL_ERROR "no board description ${FACET_BOARD_JSON}")
    endif()
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${FACET_BOARD_JSON})
    file(READ ${FACET_BOARD_JSON} _json)
    string(JSON _n LENGTH "${_json}" cpu_flags)
    set(FACET_CPU_FLAGS "")
    math(EXPR _last "${_n} - 1")
    foreach(_i RANGE ${_last})
        string(JSON _f GET "${_json}" cpu_flags ${_i})
        list(APPEND FACET_CPU_FLAGS ${_f})
    endforeach()
    # Optional keys: "qemu" (QEMU boards), "linker" (a script shared with another board: the
    # EVKB's stand-in links with the EVKB's), pack "writable" (false: the pack sits in flash and
    # a deflated one is inflated into "memory" bytes of RAM; true: inflated in place).
    string(JSON FACET_QEMU_MACHINE ERROR_VARIABLE _noqemu GET "${_json}" qemu machine)
    foreach(_cap screenshots mouse touch bench flash_runner)
        string(TOUPPER ${_cap} _CAP)
        facet_board_capability(${board} ${_cap} FACET_BOARD_${_CAP})
        if(FACET_BOARD_${_CAP})
            set(_${_cap}_cpp true)
        else()
            set(_${_cap}_cpp false)
        endif()
    endforeach()
    string(JSON _linker ERROR_VARIABLE _nolinker GET "${_json}" linker)
    if(_nolinker)
        set(_linker ${board})
    endif()
    string(JSON _pack_writable ERROR_VARIABLE _nowritable GET "${_json}" pack writable)
    if(_nowritable)
        set(_pack_writable ON)
    endif()
    string(JSON _flash_origin ERROR_VARIABLE _noflash GET "${_json}" flash origin)
    string(JSON _flash_bytes ERROR_VARIABLE _noflash GET "${_json}" flash bytes)
    set(_flash_ld "")
    if(NOT _noflash)
        set(_flash_ld "/* The whole flash device (firmware and pack regions): the MPU's read-only region. */
__flash_device_start = ${_flash_origin};
__flash_device_end = ${_flash_origin} + ${_flash_bytes};
")
    endif()
    string(JSON _pack_memory ERROR_VARIABLE _nomemory GET "${_json}" pack memory)
    if(_nomemory)
        set(_pack_memory 0)
    endif()
    string(JSON _w GET "${_json}" display width)
    string(JSON _h GET "${_json}" display height)
    string(JSON _budget GET "${_json}" ram_budget)
    string(JSON _stack GET "${_json}" stack)
    string(JSON _pack GET "${_json}" pack address)
    string(JSON _pack_size GET "${_json}" pack bytes)
    string(JSON _fault_probe ERROR_VARIABLE _noprobe GET "${_json}" fault_probe)
    if(_noprobe)
        set(_fault_probe ${_budget})
    endif()
    facet_board_bytes(${_budget} _budget_bytes)
    facet_board_bytes(${_pack} _pack_address)
    facet_board_bytes(${_pack_size} _pack_bytes)
    facet_board_bytes(${_pack_memory} _pack_memory_bytes)
    facet_board_bytes(${_fault_probe} _fault_probe_address)
    if(_pack_writable)
        set(_pack_writable_cpp true)
    else()
        set(_pack_writable_cpp false)
    endif()
    set(FACET_BOARD_GENERATED ${CMAKE_BINARY_DIR}/board)
    set(_mem "")
    string(JSON _regions LENGTH "${_json}" memory)
    math(EXPR _last "${_regions} - 1")
    foreach(_i RANGE ${_last})
        string(JSON _rn GET "${_json}" memory ${_i} name)
        string(JSON _ra GET "${_json}" memory ${_i} attributes)
        string(JSON _ro GET "${_json}" memory ${_i} origin)
        string(JSON _rb GET "${_json}" memory ${_i} bytes)
        string(APPEND _mem "    ${_rn} (${_ra}) : ORIGIN = ${_ro}, LENGTH = ${_rb}\n")
    endforeach()
    file(WRITE ${FACET_BOARD_GENERATED}/board_memory.ld.in
"/* Generated from boards/${board}/board.json by cmake/facet.cmake: edit that file, not this. */
MEMORY
{
${_mem}}
STACK_SIZE = ${_stack};
/* The pack (exact geometry), written by QEMU's loader (or flashed) before boot: an address
   range, not a section, so the ELF has no load segment there to collide with it. */
__pack_start = ${_pack};
__pack_end = __pack_start + ${_pack_size};
PACK_MEMORY_SIZE = ${_pack_memory_bytes};
__ram_budget = ${_budget};
${_flash_ld}")
    configure_file(${FACET_BOARD_GENERATED}/board_memory.ld.in ${FACET_BOARD_GENERATED}/board_memory.ld COPYONLY)
    file(WRITE ${FACET_BOARD_GENERATED}/facet_board_config.h.in
"#pragma once
// Generated from boards/${board}/board.json by cmake/facet.cmake: edit that file, not this.
// What the firmware sizes its static buffers from; only firmware sees it.
#include <cstdint>

namespace facet::board_config {
constexpr const char* kName = \"${board}\";
constexpr uint16_t kDisplayWidth = ${_w};
constexpr uint16_t kDisplayHeight = ${_h};
constexpr uint32_t kRamBytes = ${_budget_bytes}u;  // the RAM budget (${_budget})
constexpr uintptr_t kPackAddress = ${_pack_address}u; // ${_pack}: where the pack file is loaded
constexpr uint32_t kPackBytes = ${_pack_bytes}u;   // its room (${_pack_size})
// false: the pack region is read-only (flash); a deflated pack is inflated into kPackMemoryBytes
// of RAM the firmware reserves. true: it is inflated in place, in the pack region.
constexpr bool kPackWritable = ${_pack_writable_cpp};
constexpr uint32_t kPackMemoryBytes = ${_pack_memory_bytes}u;
// Where facet-fault-test stores: the first address past the RAM the board grants.
constexpr uintptr_t kFaultProbe = ${_fault_probe_address}u;
// What it can do (board.json \"capabilities\"; its drivers say the same at run time).
constexpr bool kMouse = ${_mouse_cpp}, kTouch = ${_touch_cpp}, kScreenshots = ${_screenshots_cpp};
} // namespace facet::board_config
")
    configure_file(${FACET_BOARD_GENERATED}/facet_board_config.h.in ${FACET_BOARD_GENERATED}/facet_board_config.h COPYONLY)
    set(FACET_LINKER_SCRIPT ${CMAKE_SOURCE_DIR}/linker/${_linker}.ld)
    # A board that boots from flash and is not QEMU's: its firmware gets .bin and .hex images.
    foreach(_i RANGE ${_last})
        string(JSON _rn GET "${_json}" memory ${_i} name)
        if(_rn STREQUAL "FLASH")
            string(JSON _rb GET "${_json}" memory ${_i} bytes)
            facet_board_bytes(${_rb} FACET_FLASH_FIRMWARE_BYTES)
        endif()
    endforeach()
    if(NOT _noflash AND _noqemu)
        set(FACET_BOARD_FLASH_IMAGE ON)
    else()
        set(FACET_BOARD_FLASH_IMAGE OFF)
    endif()
endmacro()

# Builds that do not depend on where the tree was checked out: __FILE__ (the asserts' messages)
# relative to the source folder, so the same source makes the same image anywhere (and
# docs/budgets.md's code sizes hold on every clone).
add_compile_options(-fmacro-prefix-map=${CMAKE_SOURCE_DIR}/=)

if(CMAKE_CROSSCOMPILING)
    set(FACET_TARGET_BUILD ON)
    if(NOT FACET_BOARD)
        message(FATAL_ERROR "FACET_BOARD is required for an ARM build (a folder of boards/ with a board.json)")
    endif()
    facet_read_board(${FACET_BOARD})

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
        # Comparison tracing finds magic bytes (the pack's tags and sizes); the geometry's
        # comparisons are against computed floats, where it only costs time: off, the
        # tessellate target runs ~4x the executions (docs/reliability.md, long runs).
        option(FACET_FUZZ_TRACE_CMP "libFuzzer comparison tracing in every library" ON)
        if(NOT FACET_FUZZ_TRACE_CMP)
            add_compile_options(-fno-sanitize-coverage=trace-cmp)
        endif()
    endif()
endif()

# facet_firmware(<name> SOURCES ...): a firmware ELF for the configured board. A board that
# boots from flash (board.json "flash") also gets <name>.bin (the flash image from its first
# byte) and <name>.hex, and the link prints the image size against the firmware's flash room.
function(facet_firmware name)
    cmake_parse_arguments(FW "" "" "SOURCES;LIBS" ${ARGN})
    add_executable(${name} ${FW_SOURCES})
    set_target_properties(${name} PROPERTIES SUFFIX ".elf")
    target_link_libraries(${name} PRIVATE facet_board facet_board_common ${FW_LIBS})
    if(TARGET facet_qemu)
        target_link_libraries(${name} PRIVATE facet_qemu)
    endif()
    target_link_options(${name} PRIVATE -L${FACET_BOARD_GENERATED} -L${CMAKE_SOURCE_DIR}/linker -T${FACET_LINKER_SCRIPT}
                        -Wl,-Map=$<TARGET_FILE:${name}>.map)
    file(GLOB _fragments ${CMAKE_SOURCE_DIR}/linker/*-itcm.ld)
    set_target_properties(${name} PROPERTIES LINK_DEPENDS
        "${FACET_LINKER_SCRIPT};${FACET_BOARD_GENERATED}/board_memory.ld;${_fragments}")
    if(FACET_BOARD_FLASH_IMAGE)
        add_custom_command(TARGET ${name} POST_BUILD
            COMMAND ${CMAKE_OBJCOPY} -O binary -j .boot_hdr -j .vectors -j .itcm_text -j .text -j .ARM.exidx
                    -j .init_array -j .data $<TARGET_FILE:${name}> $<TARGET_FILE_DIR:${name}>/${name}.bin
            COMMAND ${CMAKE_OBJCOPY} -O ihex -j .boot_hdr -j .vectors -j .itcm_text -j .text -j .ARM.exidx
                    -j .init_array -j .data $<TARGET_FILE:${name}> $<TARGET_FILE_DIR:${name}>/${name}.hex
            COMMAND ${CMAKE_COMMAND} -DIMAGE=$<TARGET_FILE_DIR:${name}>/${name}.bin -DROOM=${FACET_FLASH_FIRMWARE_BYTES}
                    -P ${CMAKE_SOURCE_DIR}/cmake/image_size.cmake
            VERBATIM)
    endif()
endfunction()
