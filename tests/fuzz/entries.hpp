// What each fuzz target does with its bytes, shared by the libFuzzer targets (POSTPROC_FUZZ) and by
// the regression test that replays tests/fuzz/regressions/<target>/* under the normal ASan build.
// An entry returns normally for any input: errors of the input (InputError, gppl::Error, ...) are
// caught here; anything else escaping, a sanitizer report, a hang or a broken round trip (abort)
// is a finding.
#pragma once

#include <string_view>

namespace fuzz {

void trace_reader(std::string_view data);    // read, check the catalogue types, write, read back the same; skim
void gppl_check(std::string_view data);      // compile a post
void gppl_run(std::string_view data);        // compile a post and run it on a small job, bounded
void display_format(std::string_view data);  // parse a display format, apply it to a few values
void prp_loader(std::string_view data);      // load a PRP (both unit halves), write it, load that again
void pikocnc(std::string_view data);         // read PikoCNC G-code back into motion, bounded
void vmid(std::string_view data);            // load a VMID machine file (XML) like prp_loader: load, write, load
void twoaxis(std::string_view data);         // read a 2XAxisCNC program back into stream commands
void sinumerik(std::string_view data);       // read a Sinumerik program back into stream commands
void iso(std::string_view data);             // read a Fanuc/LinuxCNC/Mach3/GRBL program (first byte: which)
void controllers(std::string_view data);     // every registered controller's reader (bytes 1-2: which, how)
void pikocnc_script(std::string_view data);
void lsp(std::string_view data);
void tool_table(std::string_view data);      // parse a controller tool table (LinuxCNC format)             // a language server session: framed JSON-RPC messages, replies discarded  // parse, check and run a PikoCNC script, bounded, output discarded

// The entry of a target by name (the folder names under regressions/); nullptr when unknown.
using Entry = void (*)(std::string_view);
Entry entry(std::string_view target);

}  // namespace fuzz
