// The one instruction table (docs/program.md "Instructions"): every fact the
// compiler needs about a mnemonic — its role in a rung, operand forms, cost
// class, families, pulse form and handler.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "program/engine.hpp"

namespace slmp::program::detail {

// How an instruction takes part in the rung (the compiler's result-stack check, docs/program.md "Instructions").
enum class Role : std::uint8_t {
    Load,        // LD-class: starts a rung or opens a block
    Combine,     // AND/OR-class: needs an open value
    Join,        // ANB/ORB: joins the last two blocks
    BranchPush,  // MPS
    BranchRead,  // MRD
    BranchPop,   // MPP
    Modify,      // INV, MEP, MEF: change r in place
    Output,      // needs exactly one open value; more outputs may follow on the same r
    Master,      // MC: an output that ends the rung
    Free,        // no condition (END, FEND, NOP, MCR, FOR, NEXT, RET, JMP): ends the rung
};

// Operand types, one letter per operand (compile.cpp resolves them):
//   b bit read          o bit write (no X)       x bit device start (block of bits written)
//   y bit device start (block of bits read)
//   w 16-bit source     W 16-bit destination     n count (16-bit source)
//   d 32-bit source     D 32-bit destination
//   v 16-bit destination of two words (/: quotient, remainder)
//   V 32-bit destination of four words (D*, D/)
//   e float source      E float destination
//   q word device start (block of words)         z any device start (ZRST)
//   s string source     p pointer                N nesting level
struct Form {
    std::string_view types;
    std::string_view names;   // "s1 s2 d", for messages
};

struct InstructionInfo {
    std::string_view mnemonic;
    Role role;
    Cost cost;
    std::uint8_t families;        // FamilyBits
    bool pulse_form;              // MNEMONIC + "P" executes on the rising edge (docs/program.md "Instructions")
    bool edge;                    // owns an edge bit itself (LDP, PLS, SCJ ...)
    bool swap_two;                // the short form "s d" means d := d op s (+, -, E+, WAND ...)
    std::uint8_t form_count;
    std::array<Form, 2> forms;
    Handler handler;              // the step's handler (application instructions check r themselves)
    std::string_view q_name;      // an FX name: the Q name to suggest outside iQ-F ("+")
    std::uint8_t variant = 0;     // handler-specific
};

// Exact (upper-case) lookup; P forms are looked up by the compiler through pulse_form.
const InstructionInfo* find_instruction(std::string_view mnemonic);
// Mnemonics MELSEC CPUs have that slmp-sim does not run yet (a load error says so).
bool known_but_unsupported(std::string_view mnemonic);

}  // namespace slmp::program::detail
