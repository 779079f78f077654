// Every command handler, one family per file in this folder, and the
// decoders of the device commands (request data -> Operands, in decode()).
#pragma once

#include "protocol/command_table.hpp"

namespace slmp::protocol::commands {

// device_batch.cpp — Read 0401 / Write 1401, subcommands 0000–0003 and 0080–0083.
void decode_batch(DecodeContext& d);
EndCode batch_read(CommandContext& ctx);
EndCode batch_write(CommandContext& ctx);

// device_random.cpp — Read Random 0403, Write Random 1402 (words; bits),
// Entry Monitor Device 0801, Execute Monitor 0802.
void decode_random_read(DecodeContext& d);
void decode_random_write_words(DecodeContext& d);
void decode_random_write_bits(DecodeContext& d);
void decode_monitor(DecodeContext& d);
EndCode random_read(CommandContext& ctx);
EndCode random_write_words(CommandContext& ctx);
EndCode random_write_bits(CommandContext& ctx);
EndCode monitor_register(CommandContext& ctx);
EndCode monitor_execute(CommandContext& ctx);

// device_1e.cpp — the A-compatible 1E frame's batch read/write (00-03) and
// test bit units (04); 05 and 07 use the 3E decoders (protocol/frame_1e.cpp).
void decode_batch_1e(DecodeContext& d);
void decode_test_bits_1e(DecodeContext& d);

// device_block.cpp — Read Block 0406 / Write Block 1406.
void decode_block_read(DecodeContext& d);
void decode_block_write(DecodeContext& d);
EndCode block_read(CommandContext& ctx);
EndCode block_write(CommandContext& ctx);

// buffer_memory.cpp — Memory Read/Write 0613/1613, Extend Unit Read/Write 0601/1601.
EndCode memory_read(CommandContext& ctx);
EndCode memory_write(CommandContext& ctx);
EndCode extend_unit_read(CommandContext& ctx);
EndCode extend_unit_write(CommandContext& ctx);

// labels.cpp — Array Label Read/Write 041A/141A, Label Read/Write Random 041C/141B.
EndCode array_label_read(CommandContext& ctx);
EndCode array_label_write(CommandContext& ctx);
EndCode label_read_random(CommandContext& ctx);
EndCode label_write_random(CommandContext& ctx);

// cpu_model.cpp — Read Type Name 0101.
EndCode read_type_name(CommandContext& ctx);
EndCode read_pc_type_1e(CommandContext& ctx);   // 1E 15

// loopback.cpp — Self Test 0619.
EndCode self_test(CommandContext& ctx);
EndCode self_test_1e(CommandContext& ctx);   // 1E 16

// remote.cpp — Remote RUN 1001, STOP 1002, PAUSE 1003, Latch Clear 1005,
// RESET 1006, and Clear Error 1617 (the same operating-state rules).
EndCode remote_run(CommandContext& ctx);
EndCode remote_stop(CommandContext& ctx);
EndCode remote_pause(CommandContext& ctx);
EndCode remote_latch_clear(CommandContext& ctx);
EndCode remote_reset(CommandContext& ctx);
EndCode clear_error(CommandContext& ctx);
EndCode remote_run_1e(CommandContext& ctx);    // 1E 13
EndCode remote_stop_1e(CommandContext& ctx);   // 1E 14

// files.cpp — File control 1810 Read Directory, 1811 Search, 1820 New,
// 1822 Delete, 1824 Copy, 1825 Change State, 1826 Change Date, 1827 Open,
// 1828 Read, 1829 Write, 182A Close (devicemodel/drives.hpp, docs/files.md).
EndCode file_list(CommandContext& ctx);
EndCode file_search(CommandContext& ctx);
EndCode file_new(CommandContext& ctx);
EndCode file_delete(CommandContext& ctx);
EndCode file_copy(CommandContext& ctx);
EndCode file_state(CommandContext& ctx);
EndCode file_date(CommandContext& ctx);
EndCode file_open(CommandContext& ctx);
EndCode file_read(CommandContext& ctx);
EndCode file_write(CommandContext& ctx);
EndCode file_close(CommandContext& ctx);

// password.cpp — Remote Password Unlock 1630 / Lock 1631.
EndCode password_unlock(CommandContext& ctx);
EndCode password_lock(CommandContext& ctx);

// node.cpp — the node commands of the Japanese manual (JA §3.12-3.14): Node
// Search 0E30, IP Address Set 0E31, Device Info Compare 0E32, Parameter Get
// 0E33 / Set 0E34 / Set Start 0E35 / Set End 0E36 / Set Cancel 0E3A, Status
// Read 0E44, Communication Setting Get 0E45, Status Read2 0E53.
EndCode node_search(CommandContext& ctx);
EndCode ip_address_set(CommandContext& ctx);
EndCode device_info_compare(CommandContext& ctx);
EndCode parameter_get(CommandContext& ctx);
EndCode parameter_set(CommandContext& ctx);
EndCode parameter_set_start(CommandContext& ctx);
EndCode parameter_set_end(CommandContext& ctx);
EndCode parameter_set_cancel(CommandContext& ctx);
EndCode status_read(CommandContext& ctx);
EndCode status_read2(CommandContext& ctx);
EndCode communication_setting_get(CommandContext& ctx);

}  // namespace slmp::protocol::commands
