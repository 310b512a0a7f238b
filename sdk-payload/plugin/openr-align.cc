// openr-align.cc - the SDK's gcc plugin: a cheap alignment trap, and MIPS inline
// assembly left out (at the end of this file).
//
// mipsel-linux-g++ builds with -fsanitize=alignment: the robot's MIPS CPU faults on a
// misaligned load or store, x86 does not.  gcc puts an internal check (UBSAN_NULL) at
// every access, checks against the PC's alignment of the type and, at the end of the
// optimisation pipeline, turns it into a call of a handler that may return (an 8-byte
// long at a 4-byte address is fine on the robot, whose long is a 4-byte word).  Until
// then the check counts as a store to any memory, so a loop that adds to a member
// reloads it from memory on every pass: pixel loops run about twice as slowly.
//
// This pass runs right after gcc places the checks and replaces each one by the check
// the robot would make: the address against the type's alignment on the robot (a word
// at most 4, a double 8), and on failure a call of the handler that never returns
// (libmcoopstub's __ubsan_handle_type_mismatch_v1_abort faults the object).  A check
// that cannot fail is dropped.  The code that follows knows the address was aligned
// and nothing else: the optimisers keep values in registers and hoist checks out of
// loops, as without the trap.
//
// With -fno-sanitize-recover=alignment the user asked for the PC's alignment to be
// fatal: then the check keeps the PC's alignment (and the same handler).  With
// -fsanitize=null (OPENR_SANITIZE=undefined) gcc's own expansion and libubsan's
// handlers stay: the pass does nothing.
#include "gcc-plugin.h"
#include "plugin-version.h"
#include "backend.h"
#include "tree.h"
#include "gimple.h"
#include "tree-pass.h"
#include "context.h"
#include "ssa.h"
#include "cfghooks.h"
#include "cfgloop.h"
#include "gimple-iterator.h"
#include "tree-into-ssa.h"
#include "internal-fn.h"
#include "attribs.h"
#include "asan.h"
#include "ubsan.h"
#include "builtins.h"
#include "fold-const.h"
#include "diagnostic-core.h"

int plugin_is_GPL_compatible;

namespace {

// The alignment the robot's CPU needs for an access of `type` that the PC wants
// `host`-byte aligned: a double 8 (ldc1/sdc1), anything else at most a word.  The same
// rule as libmcoopstub's handler (ubsan.cc), which words the fault.
// A floating type the robot loads and stores with ldc1/sdc1: a double (its long double is
// a double too).
bool robot_double(tree type)
{
    return TREE_CODE(type) == REAL_TYPE && TYPE_PRECISION(type) >= 64;
}

unsigned HOST_WIDE_INT robot_alignment(tree type, unsigned HOST_WIDE_INT host)
{
    // A double the PC's type says is less aligned (packed, aligned(4)) was less aligned for
    // the robot's gcc too, which then used word loads.
    if (robot_double(type)) return host < 8 ? host : 8;
    return host < 4 ? host : 4;
}

// -fsanitize-undefined-trap-on-error (gcc 12) / -fsanitize-trap=alignment (gcc 13 on):
// a trap instruction instead of the handler, as gcc's own expansion does.
bool trap_on_error()
{
#ifdef flag_sanitize_trap
    return (flag_sanitize_trap & SANITIZE_ALIGNMENT) != 0;
#else
    return flag_sanitize_undefined_trap_on_error != 0;
#endif
}

// What one check tests: the address `ptr + offset` against `need` bytes; the handler is
// told `type` (an access of it) and the PC's alignment `host`.
struct Check {
    tree type;
    unsigned HOST_WIDE_INT host;
    unsigned HOST_WIDE_INT need;
    HOST_WIDE_INT offset;
};

// gcc checks a member access `p->d` against the whole object's type. If the statement
// the check guards (the next one) loads or stores a double member at a constant place,
// the robot's ldc1/sdc1 want that double 8-byte aligned: the check becomes one of the
// double's own address. Otherwise null.
tree double_at(tree ref, tree ptr, HOST_WIDE_INT* offset);

tree guarded_double(gimple_stmt_iterator gsi, tree ptr, HOST_WIDE_INT* offset)
{
    gsi_next_nondebug(&gsi);
    if (gsi_end_p(gsi) || !is_gimple_assign(gsi_stmt(gsi))) return NULL_TREE;
    gimple* s = gsi_stmt(gsi);
    // A load or a store (the kind of a C++ member access does not say which).
    tree d = double_at(gimple_assign_lhs(s), ptr, offset);
    return d ? d : double_at(gimple_assign_rhs1(s), ptr, offset);
}

// The type of `ref` if it is a double at a constant place in `*ptr` (its offset in
// `offset`), else null.
tree double_at(tree ref, tree ptr, HOST_WIDE_INT* offset)
{
    tree type = TREE_TYPE(ref);
    // Where gcc knows the double to be less than 8-aligned (a packed struct), the robot's
    // gcc used word accesses.
    if (!robot_double(type) || !handled_component_p(ref) || get_object_alignment(ref) < 64) return NULL_TREE;
    poly_int64 bitsize, bitpos;
    tree varying;
    machine_mode mode;
    int unsignedp, reversep, volatilep;
    tree base = get_inner_reference(ref, &bitsize, &bitpos, &varying, &mode, &unsignedp, &reversep, &volatilep);
    HOST_WIDE_INT bits;
    if (TREE_CODE(base) != MEM_REF || TREE_OPERAND(base, 0) != ptr || !bitpos.is_constant(&bits) || bits % BITS_PER_UNIT)
        return NULL_TREE;
    // A varying part (an array index) that is a multiple of 8 leaves the double's address
    // mod 8 where the constant part puts it.
    if (varying && tree_ctz(varying) < 3) return NULL_TREE;
    poly_int64 extra;
    HOST_WIDE_INT more;
    if (!mem_ref_offset(base).to_shwi(&extra) || !extra.is_constant(&more)) return NULL_TREE;
    *offset = bits / BITS_PER_UNIT + more;
    return type;
}

// Replaces the UBSAN_NULL at `gsi` by
//   a = (uintptr) ptr + offset; if ((a & (need - 1)) != 0) handler_abort (&data, a);
// The rest of the original block moves to a new block after the fault block.
void lower(gimple_stmt_iterator* gsi, const Check& c)
{
    gimple* stmt = gsi_stmt(*gsi);
    location_t loc = gimple_location(stmt);
    tree ptr = gimple_call_arg(stmt, 0);
    tree ckind = gimple_call_arg(stmt, 1);
    unsigned HOST_WIDE_INT need = c.need;

    tree addr = make_ssa_name(pointer_sized_int_node);
    gimple* g = gimple_build_assign(addr, NOP_EXPR, ptr);
    gimple_set_location(g, loc);
    gsi_insert_before(gsi, g, GSI_SAME_STMT);
    if (c.offset != 0) {
        tree base = addr;
        addr = make_ssa_name(pointer_sized_int_node);
        g = gimple_build_assign(addr, PLUS_EXPR, base, build_int_cst(pointer_sized_int_node, c.offset));
        gimple_set_location(g, loc);
        gsi_insert_before(gsi, g, GSI_SAME_STMT);
    }
    tree low = make_ssa_name(pointer_sized_int_node);
    g = gimple_build_assign(low, BIT_AND_EXPR, addr, build_int_cst(pointer_sized_int_node, need - 1));
    gimple_set_location(g, loc);
    gsi_insert_before(gsi, g, GSI_SAME_STMT);

    // The block is split after the check: the check's block ends in the condition.
    basic_block cond_bb = gimple_bb(stmt);
    edge e = split_block(cond_bb, stmt);
    e->flags = EDGE_FALSE_VALUE;
    basic_block fault_bb = create_empty_bb(cond_bb);
    edge te = make_edge(cond_bb, fault_bb, EDGE_TRUE_VALUE);
    te->probability = profile_probability::never();
    e->probability = te->probability.invert();
    fault_bb->count = te->count();
    if (dom_info_available_p(CDI_DOMINATORS)) set_immediate_dominator(CDI_DOMINATORS, fault_bb, cond_bb);
    // The fault block never returns to a loop, so it belongs to none but the function's
    // (the root of the loop tree); its edge leaves any loop the check is in.
    if (current_loops) {
        add_bb_to_loop(fault_bb, current_loops->tree_root);
        loops_state_set(LOOPS_NEED_FIXUP);
    }

    // The handler call: gcc's data for it (source position, the type, the PC's
    // alignment, what kind of access), as gcc's own expansion makes it.
    tree data = ubsan_create_data("__ubsan_null_data", 1, &loc,
                                  ubsan_type_descriptor(build_pointer_type(c.type), UBSAN_PRINT_POINTER), NULL_TREE,
                                  build_int_cst(unsigned_char_type_node, exact_log2(c.host)),
                                  fold_convert(unsigned_char_type_node, ckind), NULL_TREE);
    data = build_fold_addr_expr_loc(loc, data);
    if (trap_on_error())
        g = gimple_build_call(builtin_decl_explicit(BUILT_IN_TRAP), 0);
    else
        g = gimple_build_call(builtin_decl_explicit(BUILT_IN_UBSAN_HANDLE_TYPE_MISMATCH_V1_ABORT), 2, data, addr);
    gimple_set_location(g, loc);
    gimple_stmt_iterator fgsi = gsi_start_bb(fault_bb);
    gsi_insert_after(&fgsi, g, GSI_NEW_STMT);

    unlink_stmt_vdef(stmt);
    g = gimple_build_cond(NE_EXPR, low, build_int_cst(pointer_sized_int_node, 0), NULL_TREE, NULL_TREE);
    gimple_set_location(g, loc);
    gsi_replace(gsi, g, false);
}

const pass_data align_pass_data = {
    GIMPLE_PASS,
    "openr-align",
    OPTGROUP_NONE,
    TV_NONE,
    PROP_ssa | PROP_cfg,
    0,
    0,
    0,
    TODO_update_ssa_only_virtuals | TODO_cleanup_cfg,
};

struct align_pass : gimple_opt_pass {
    align_pass(gcc::context* ctx) : gimple_opt_pass(align_pass_data, ctx) {}

    // OPENR_ALIGNMENT_TRAP=ubsan asks for gcc's own check (the plugin is loaded for its
    // other pass all the same).
    bool gate(function*) final override
    {
        const char* trap = getenv("OPENR_ALIGNMENT_TRAP");
        bool own = trap && strcmp(trap, "ubsan") == 0;
        return (flag_sanitize & SANITIZE_ALIGNMENT) && !(flag_sanitize & SANITIZE_NULL) && !own;
    }

    unsigned int execute(function* fun) final override
    {
        bool recover = (flag_sanitize_recover & SANITIZE_ALIGNMENT) != 0;
        bool changed = false;
        initialize_sanitizer_builtins();
        basic_block bb;
        // Blocks made by the splits are visited too (they hold the rest of a block).
        FOR_EACH_BB_FN(bb, fun)
        {
            for (gimple_stmt_iterator gsi = gsi_start_bb(bb); !gsi_end_p(gsi);) {
                gimple* stmt = gsi_stmt(gsi);
                if (!gimple_call_internal_p(stmt, IFN_UBSAN_NULL) || integer_zerop(gimple_call_arg(stmt, 2))) {
                    gsi_next(&gsi);
                    continue;
                }
                tree ptr = gimple_call_arg(stmt, 0);
                tree ckind = gimple_call_arg(stmt, 1);
                tree type = TREE_TYPE(TREE_TYPE(ckind));
                unsigned HOST_WIDE_INT host = tree_to_uhwi(gimple_call_arg(stmt, 2));
                Check c = {type, host, recover ? robot_alignment(type, host) : host, 0};
                unsigned HOST_WIDE_INT kind = tree_to_uhwi(ckind);
                bool access = kind == UBSAN_LOAD_OF || kind == UBSAN_STORE_OF || kind == UBSAN_MEMBER_ACCESS;
                if (recover && AGGREGATE_TYPE_P(type) && access) {
                    HOST_WIDE_INT offset;
                    if (tree d = guarded_double(gsi, ptr, &offset)) c = {d, 8, 8, offset};
                }
                // Binding a reference, a call or a cast reads nothing: no ldc1 there.
                if (recover && !access && c.need > 4) c.need = 4;
                changed = true;
                bool aligned = c.offset % (HOST_WIDE_INT)c.need == 0 && get_pointer_alignment(ptr) / BITS_PER_UNIT >= c.need;
                if (c.need <= 1 || aligned) {
                    unlink_stmt_vdef(stmt);
                    gsi_remove(&gsi, true);
                    continue;
                }
                lower(&gsi, c);
                // The block ends at the check now; the walk goes on with the fault block,
                // then the block holding the rest.
                break;
            }
        }
        if (changed) mark_virtual_operands_for_renaming(fun);
        return 0;
    }
};

// MIPS inline assembly of the program's own code (`asm volatile ("mfc0 %0, $9" : "=r"
// (count))`, `__asm__ __volatile__ ("sync")`): the PC cannot run it, and the compiler
// wrapper's -Dasm(...)= only reaches a plain `asm (`. Each asm statement outside the
// system's headers is left out; its outputs become 0, and a note says so.
const pass_data asm_pass_data = {
    GIMPLE_PASS,
    "openr-mips-asm",
    OPTGROUP_NONE,
    TV_NONE,
    PROP_ssa | PROP_cfg,
    0,
    0,
    0,
    TODO_update_ssa_only_virtuals,
};

const char* skip_blanks(const char* t)
{
    while (*t == ' ' || *t == '\t' || *t == '\n' || *t == '\r') t++;
    return t;
}

bool clobbers_memory(gasm* stmt)
{
    for (unsigned i = 0; i < gimple_asm_nclobbers(stmt); i++)
        if (strcmp(TREE_STRING_POINTER(TREE_VALUE(gimple_asm_clobber_op(stmt, i))), "memory") == 0) return true;
    return false;
}

// What output `i` (constraint `constraint`) holds once its asm is left out: nothing new
// for an in-out operand ("+r"), the input tied to it ("0"), else 0 -- or null when
// nothing can be assigned (an array of unknown or varying size).
tree output_value(gasm* stmt, unsigned i, const char* constraint)
{
    tree out = TREE_VALUE(gimple_asm_output_op(stmt, i));
    if (strchr(constraint, '+')) return NULL_TREE;
    char tie[16];
    snprintf(tie, sizeof(tie), "%u", i);
    for (unsigned k = 0; k < gimple_asm_ninputs(stmt); k++) {
        tree in = gimple_asm_input_op(stmt, k);
        tree value = TREE_VALUE(in);
        if (strcmp(TREE_STRING_POINTER(TREE_VALUE(TREE_PURPOSE(in))), tie) != 0) continue;
        bool scalar = INTEGRAL_TYPE_P(TREE_TYPE(out)) || POINTER_TYPE_P(TREE_TYPE(out)) || SCALAR_FLOAT_TYPE_P(TREE_TYPE(out));
        return scalar && is_gimple_val(value) && useless_type_conversion_p(TREE_TYPE(out), TREE_TYPE(value)) ? value : NULL_TREE;
    }
    tree size = TYPE_SIZE_UNIT(TREE_TYPE(out));
    if (!size || TREE_CODE(size) != INTEGER_CST) return NULL_TREE;
    return build_zero_cst(TREE_TYPE(out));
}

struct asm_pass : gimple_opt_pass {
    asm_pass(gcc::context* ctx) : gimple_opt_pass(asm_pass_data, ctx) {}

    unsigned int execute(function* fun) final override
    {
        bool changed = false;
        basic_block bb;
        FOR_EACH_BB_FN(bb, fun)
        {
            for (gimple_stmt_iterator gsi = gsi_start_bb(bb); !gsi_end_p(gsi);) {
                gasm* stmt = dyn_cast<gasm*>(gsi_stmt(gsi));
                location_t loc = stmt ? gimple_location(stmt) : UNKNOWN_LOCATION;
                // asm goto jumps: its edges stay, and so does it (the assembler names it).
                if (!stmt || gimple_asm_nlabels(stmt) > 0 || loc == UNKNOWN_LOCATION || in_system_header_at(loc)) {
                    gsi_next(&gsi);
                    continue;
                }
                // An empty template runs on any CPU (a compiler barrier, a value laundered).
                if (!*skip_blanks(gimple_asm_string(stmt))) {
                    gsi_next(&gsi);
                    continue;
                }
                unsigned outputs = gimple_asm_noutputs(stmt);
                for (unsigned i = 0; i < outputs; i++) {
                    tree op = gimple_asm_output_op(stmt, i);
                    tree out = TREE_VALUE(op);
                    tree value = output_value(stmt, i, TREE_STRING_POINTER(TREE_VALUE(TREE_PURPOSE(op))));
                    if (!value) continue;
                    gimple* set = gimple_build_assign(out, value);
                    gimple_set_location(set, loc);
                    gsi_insert_before(&gsi, set, GSI_SAME_STMT);
                }
                // A memory clobber (a `sync`) is kept as a compiler barrier.
                if (clobbers_memory(stmt)) {
                    vec<tree, va_gc>* clobbers = NULL;
                    vec_safe_push(clobbers, build_tree_list(NULL_TREE, build_string(7, "memory")));
                    gasm* barrier = gimple_build_asm_vec("", NULL, NULL, clobbers, NULL);
                    gimple_asm_set_volatile(barrier, true);
                    gimple_set_location(barrier, loc);
                    gsi_insert_before(&gsi, barrier, GSI_SAME_STMT);
                }
                inform(loc, "%s MIPS inline assembly left out: the PC cannot run it%s", "[cargo-openr]",
                       outputs ? "; its outputs are 0 (an in-out operand keeps its value)" : "");
                unlink_stmt_vdef(stmt);
                gsi_remove(&gsi, true);
                changed = true;
            }
        }
        if (changed) mark_virtual_operands_for_renaming(fun);
        return 0;
    }
};

} // namespace

int plugin_init(struct plugin_name_args* info, struct plugin_gcc_version* version)
{
    if (!plugin_default_version_check(version, &gcc_version)) {
        error("%s was built for another gcc (%s %s) than this one (%s %s): reinstall the SDK "
              "root (cargo openr sdk install)", info->base_name, gcc_version.basever,
              gcc_version.datestamp, version->basever, version->datestamp);
        return 1;
    }
    // Both right after gcc's `ubsan` pass (it places the checks), before any optimisation.
    opt_pass* passes[] = {new align_pass(g), new asm_pass(g)};
    for (opt_pass* p : passes) {
        struct register_pass_info after_ubsan;
        after_ubsan.pass = p;
        after_ubsan.reference_pass_name = "ubsan";
        after_ubsan.ref_pass_instance_number = 1;
        after_ubsan.pos_op = PASS_POS_INSERT_AFTER;
        register_callback(info->base_name, PLUGIN_PASS_MANAGER_SETUP, NULL, &after_ubsan);
    }
    static struct plugin_info about = {"2", "the robot's alignment trap, checked as the robot does; MIPS inline assembly left out"};
    register_callback(info->base_name, PLUGIN_INFO, NULL, &about);
    return 0;
}
