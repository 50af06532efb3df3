// The machine configuration a PikoCNC program runs against: what the controller takes from its own
// settings (tool table, work offsets, home and park positions) and the simulator's limits.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <set>

#include "machines/pikocnc/model/dialect.hpp"

namespace pikocnc {

// X Y Z A B.
using Axes5 = std::array<double, 5>;

struct ToolEntry {
  Axes5 offset{};       // G43 column: tool tip = holder + offset
  double radius = 0.0;  // used by G41/G42 without R
};

struct Options {
  Dialect dialect = Dialect::V2025;
  // Machine (G53.1) position of each work-offset zero, G54 .. G59.
  std::array<Axes5, 6> work_offsets{};
  std::map<int, ToolEntry> tools;
  Axes5 home1{}, home2{};                 // G28, G30 targets (G53 positions)
  std::map<int, Axes5> parks;             // G10.2 Q positions (machine positions)
  Axes5 start_position{};                 // initial work position
  double initial_feed = 0.0;              // the controller's F field
  double initial_spindle = 0.0;           // the controller's S field
  bool lathe_diameter_default = false;    // G7 as the power-on mode (import option)
  bool mdi = false;                       // execute G43/G49 (MDI-only codes)
  std::set<int> macro_m_codes;            // M3, M5, M6 configured to run a macro of that name
  int m99_restarts = 0;                   // how often M99 restarts the program before stopping
  std::size_t max_executed_lines = 100'000'000;  // runaway guard for loops and M99
  // A G25 R above this is no number of passes but a typing error (R99999999999999999999).
  double max_loop_count = 1e9;
  // Commands built in all (also while looking ahead): a runaway guard for loops and for cycles
  // whose steps never end (G83 with a tiny Q), the same bound as `postproc verify`'s.
  std::size_t max_commands = 1'000'000'000;
  bool cutter_compensation = true;        // false: G41/G42 are read but the programmed path is emitted
  bool strict_arcs = true;                // an arc whose radius cannot fit is an error (else a line)
  double arc_tolerance = 0.002;           // mm: chord longer than 2|R| by more than this is an error
  double chord_tolerance = 0.001;         // mm: arcs that stop being circles become chords
  bool comments_as_messages = true;       // every comment becomes a @message
  bool nc_lines_in_trace = false;         // attach the NC line text to the first command it produced
  std::size_t diagnostic_limit = 1000;
};

}  // namespace pikocnc
