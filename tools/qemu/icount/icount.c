/*
 * facet-icount: exact guest instruction counts between two marker functions.
 *
 *   -plugin facet-icount.so,begin=0xADDR,end=0xADDR[,limit=N][,total=on][,profile=FILE]
 *           [,profile_regions=A-B:C-D:...]
 *
 * begin/end are the addresses of facet_mark_begin and facet_mark_end (each a single return
 * instruction, see boards/common). Every translation block adds its instruction count to a
 * running total at the moment it starts (an inline add, so counting costs almost nothing);
 * the marker instructions snapshot that total. A region's count is every instruction executed
 * after the begin marker's return up to and including the call of the end marker — the end
 * marker's own return is excluded. Regions nest; each is reported when it ends, numbered in the
 * order it began:
 *
 *   facet-icount: region 3 depth 1 instructions 123456
 *
 * Interrupts must be off (or absent) in measured code for counts to repeat exactly; the facet
 * boards poll their timers and UARTs, so they are. With limit=N a region of more than N
 * instructions stops QEMU with exit code 3 and a message. With profile=FILE, every translation
 * block executed inside a region is tallied and FILE gets "address instructions block_length" lines at exit
 * (tools/qemu/profile.py maps them to functions); profile_regions restricts the tally to the
 * regions numbered A to B, C to D, ... (say, the tessellation's and not the frames').
 */
#include "qemu_plugin_api.h"

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

FACET_PLUGIN_EXPORT int qemu_plugin_version = 1;

#define MAX_DEPTH 32

static uint64_t total;           /* instructions of every translation block entered */
static uint64_t begin_addr, end_addr;
static uint64_t limit;           /* 0: none */
static int report_total;
static uint64_t open_start[MAX_DEPTH];
static uint32_t open_id[MAX_DEPTH];
static int depth;
static uint32_t next_id;
static const char* profile_path;
#define MAX_RANGES 4096
static uint32_t range_first[MAX_RANGES], range_last[MAX_RANGES];
static int ranges; /* 0: every region */
static int profiling; /* an open region is one to profile */

static int profiled(uint32_t id) {
    if (ranges == 0) return 1;
    for (int i = 0; i < ranges; ++i)
        if (id >= range_first[i] && id <= range_last[i]) return 1;
    return 0;
}

/* Profile: one record per translated block start, found by open addressing on the address. */
#define PROFILE_SLOTS (1u << 20)
struct tb_record {
    uint64_t vaddr;
    uint64_t insns;
    uint64_t executed;
};
static struct tb_record* profile_table;

static struct tb_record* profile_slot(uint64_t vaddr, uint64_t insns) {
    uint64_t h = (vaddr >> 1) * 0x9E3779B97F4A7C15ull;
    for (uint32_t probe = 0; probe < PROFILE_SLOTS; ++probe) {
        struct tb_record* r = &profile_table[(h + probe) & (PROFILE_SLOTS - 1)];
        if (r->insns == 0 || (r->vaddr == vaddr && r->insns == insns)) {
            r->vaddr = vaddr;
            r->insns = insns;
            return r;
        }
    }
    return NULL;
}

static void on_tb_exec(unsigned int vcpu, void* udata) {
    (void)vcpu;
    struct tb_record* r = udata;
    if (profiling) r->executed += r->insns;
}

static void say(const char* text) { qemu_plugin_outs(text); }

static void on_begin(unsigned int vcpu, void* udata) {
    (void)vcpu;
    (void)udata;
    if (depth == MAX_DEPTH) {
        say("facet-icount: regions nested too deeply\n");
        exit(3);
    }
    /* The begin marker's block (its return) is already in `total`: start after it. */
    open_start[depth] = total;
    open_id[depth] = next_id++;
    ++depth;
    profiling = profiling || profiled(open_id[depth - 1]);
}

static void on_end(unsigned int vcpu, void* udata) {
    (void)vcpu;
    (void)udata;
    char line[160];
    if (depth == 0) {
        say("facet-icount: end marker without a begin\n");
        return;
    }
    --depth;
    profiling = 0;
    for (int d = 0; d < depth; ++d) profiling = profiling || profiled(open_id[d]);
    /* `total` includes the end marker's own return instruction: leave it out. */
    const uint64_t count = total - open_start[depth] - 1;
    snprintf(line, sizeof line, "facet-icount: region %" PRIu32 " depth %d instructions %" PRIu64 "\n",
             open_id[depth], depth, count);
    say(line);
    if (limit && count > limit) {
        snprintf(line, sizeof line,
                 "facet-icount: region %" PRIu32 " used %" PRIu64 " instructions, over the limit of %" PRIu64 "\n",
                 open_id[depth], count, limit);
        say(line);
        fflush(stdout);
        fflush(stderr);
        exit(3);
    }
}

static void on_tb_trans(qemu_plugin_id_t id, struct qemu_plugin_tb* tb) {
    (void)id;
    const size_t n = qemu_plugin_tb_n_insns(tb);
    qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64, &total, n);
    if (profile_table && n > 0) {
        struct tb_record* r = profile_slot(qemu_plugin_insn_vaddr(qemu_plugin_tb_get_insn(tb, 0)), n);
        if (r) qemu_plugin_register_vcpu_tb_exec_cb(tb, on_tb_exec, QEMU_PLUGIN_CB_NO_REGS, r);
    }
    for (size_t i = 0; i < n; ++i) {
        struct qemu_plugin_insn* insn = qemu_plugin_tb_get_insn(tb, i);
        const uint64_t pc = qemu_plugin_insn_vaddr(insn);
        if (pc == begin_addr)
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_begin, QEMU_PLUGIN_CB_NO_REGS, NULL);
        else if (pc == end_addr)
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_end, QEMU_PLUGIN_CB_NO_REGS, NULL);
    }
}

static void on_exit_cb(qemu_plugin_id_t id, void* udata) {
    (void)id;
    (void)udata;
    char line[96];
    if (report_total) {
        snprintf(line, sizeof line, "facet-icount: total instructions %" PRIu64 "\n", total);
        say(line);
    }
    if (depth) say("facet-icount: a region was still open at exit\n");
    if (profile_table) {
        FILE* f = fopen(profile_path, "w");
        if (!f) {
            say("facet-icount: cannot write the profile\n");
            return;
        }
        for (uint32_t i = 0; i < PROFILE_SLOTS; ++i) {
            if (profile_table[i].executed)
                fprintf(f, "0x%" PRIx64 " %" PRIu64 " %" PRIu64 "\n", profile_table[i].vaddr, profile_table[i].executed,
                        profile_table[i].insns);
        }
        fclose(f);
    }
}

static int parse_u64(const char* text, uint64_t* out) {
    char* end = NULL;
    *out = strtoull(text, &end, 0);
    return end && *end == '\0' && end != text;
}

FACET_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t* info, int argc,
                                            char** argv) {
    (void)info;
    int have_begin = 0, have_end = 0;
    for (int i = 0; i < argc; ++i) {
        const char* a = argv[i];
        if (!strncmp(a, "begin=", 6)) have_begin = parse_u64(a + 6, &begin_addr);
        else if (!strncmp(a, "end=", 4)) have_end = parse_u64(a + 4, &end_addr);
        else if (!strncmp(a, "limit=", 6)) {
            if (!parse_u64(a + 6, &limit)) {
                fprintf(stderr, "facet-icount: bad limit '%s'\n", a + 6);
                return -1;
            }
        } else if (!strcmp(a, "total=on")) report_total = 1;
        else if (!strncmp(a, "profile=", 8)) profile_path = a + 8;
        else if (!strncmp(a, "profile_regions=", 16)) {
            const char* r = a + 16;
            while (*r && ranges < MAX_RANGES) {
                char* end;
                range_first[ranges] = range_last[ranges] = (uint32_t)strtoul(r, &end, 0);
                if (*end == '-') range_last[ranges] = (uint32_t)strtoul(end + 1, &end, 0);
                ++ranges;
                r = *end == ':' ? end + 1 : end;
                if (*end != ':') break;
            }
        }
        else {
            fprintf(stderr, "facet-icount: unknown argument '%s'\n", a);
            return -1;
        }
    }
    if (!have_begin || !have_end) {
        fprintf(stderr, "facet-icount: begin=ADDR and end=ADDR are required\n");
        return -1;
    }
    /* Thumb function symbols carry bit 0; instruction addresses do not. */
    begin_addr &= ~(uint64_t)1;
    end_addr &= ~(uint64_t)1;
    if (profile_path) {
        profile_table = calloc(PROFILE_SLOTS, sizeof *profile_table);
        if (!profile_table) return -1;
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_tb_trans);
    qemu_plugin_register_atexit_cb(id, on_exit_cb, NULL);
    return 0;
}
