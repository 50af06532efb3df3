// PRP machine-parameter files (SolidCAM GPPTool `machine.prp`, `.mac`, or a `.vmid` machine ID file
// mapped onto the same model) and the stream filters they imply.
//
// Contract with the engine (postproc/):
//   auto params = prp::load_file(path, job_is_inch ? prp::Units::Inch : prp::Units::Metric);
//   params.logical("arc_exist"); params.numeric("arc_max_chord"); params.text("gpp_file_ext");
//   params.records("drill_type");            // repeatable records, file order
//   params.parameters();                     // every known scalar, for exposing to the post
//   params.external_variables();             // PRP external variables to declare in GPPL
//   auto chain = prp::build_filter_chain(params, reader);  // a CommandSource the engine pulls
// See docs/prp.md for which parameters are honoured and how.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "toolpath/diagnostic.hpp"
#include "toolpath/error.hpp"
#include "toolpath/source.hpp"
#include "toolpath/value.hpp"

namespace prp {

// Which half of every metric/inch pair applies: chosen once per run from the job's unit system.
enum class Units : std::uint8_t { Metric, Inch };

// How a key's value is written (spec 1.3).
enum class ValueKind : std::uint8_t {
  Integer,      // 12, 0001
  Number,       // 10.0 or a metric/inch pair 30.0, 1.1811
  Point,        // x y z, or metric x y z ',' inch x y z
  Logical,      // Y / N (also 1/0, TRUE/FALSE), extra tokens kept
  Enumeration,  // one word of the key's set
  String,       // rest of the line, may be empty
  Record,       // repeatable multi-token record
};
std::string_view kind_name(ValueKind kind);

// Types of GPPL variables a PRP file declares (our own enum: prp does not depend on gppl).
enum class VarType : std::uint8_t { Integer, Numeric, Logical, String };
std::string_view type_name(VarType type);

// "file:line:col: error: message" or "... warning: message" (toolpath/diagnostic.hpp).
using Diagnostic = toolpath::Diagnostic;

// Loading failed: every error of the file, in file order. what() lists them, one per line.
class LoadError : public std::runtime_error {
public:
  explicit LoadError(std::vector<Diagnostic> errors);
  const std::vector<Diagnostic>& errors() const { return errors_; }

private:
  std::vector<Diagnostic> errors_;
};

// One assignment of a documented, single-valued key (the last one when a key repeats).
struct Parameter {
  std::string key;  // as written in the file (or as the spec spells it, for engine defaults)
  ValueKind kind = ValueKind::String;
  std::string raw;  // the value text as written, trimmed, comment removed
  toolpath::SourcePosition where;  // of the value; line 0 for an engine default
  std::int64_t integer = 0;        // Integer
  bool logical = false;            // Logical
  std::string text;                // String, or the Enumeration word as written
  std::array<double, 3> metric{};  // Number: [0]; Point: x y z
  std::array<double, 3> inch{};    // the inch half; equals `metric` when written without ','
  bool has_inch_half = false;
  std::vector<std::string> extra;  // tokens after a logical value (`comp_exist = Y Y`)

  bool is_default() const { return where.line == 0; }
  double number(Units units) const { return units == Units::Inch ? inch[0] : metric[0]; }
  Eigen::Vector3d point(Units units) const;
  // The value as a post sees it (the unit half chosen); nullopt for points.
  std::optional<toolpath::Value> value(Units units) const;
};

// One occurrence of a repeatable key (`drill_type = Peck Peck Y Delay`), spec 1.5.
struct Record {
  enum class Form : std::uint8_t { Declaration, Cycle };
  std::string key;   // base key, lower case, without language suffix: "drill_type"
  std::string lang;  // language suffix ("ger"), empty when none
  Form form = Form::Cycle;
  std::string name;  // variable name (Declaration) or cycle/record name (Cycle)
  std::string base;  // drill base type in canonical spelling (PECK, ...), or wc_macro's word
  std::optional<bool> flag;  // Y/N of cycle records; absent for declarations and wc_pos_type
  std::vector<std::string> params;  // user parameter names, as written
  VarType type = VarType::Numeric;  // Declaration only
  std::string raw;
  toolpath::SourcePosition where;       // of the value (a VMID: of the GppName attribute's value)
  toolpath::SourcePosition name_where;  // of the name (a VMID: the same)
};

// The parameter of a drill cycle record that holds its dwell (F_DRILL, F_BORING): the one whose name
// says `delay` or `dwell`; nullopt when no parameter or more than one does.
std::optional<std::string> dwell_parameter(const Record& record);

// A key the spec does not document: kept verbatim, so the post can still read it.
struct UnknownKey {
  std::string key;
  std::string raw;
  toolpath::SourcePosition where;
};

// A PRP external variable (spec 3.16) the engine declares in the GPPL environment.
struct ExternalVariable {
  std::string name;  // spelled as first declared
  VarType type = VarType::Numeric;
  // Initial value (typed declarations: 0, FALSE or ''), or nullopt: declared but inactive until a
  // command of the toolpath sets it (PRP cycle parameters such as `Delay`). Cycle parameters
  // (declared_by "drill_type") stay inactive even with a value (a VMID's <CycleParams> Value).
  std::optional<toolpath::Value> initial;
  std::string declared_by;  // "options", "job_opt_type", "drill_type", ... (VMID: <MachineParams> ->
                            // "options", per-job-type lists -> "job_opt_type", <CycleParams> -> "drill_type")
  toolpath::SourcePosition where;
};

// A rotary axis of the machine definition (a VMID's <Axis Type="1"> of its components) and its
// travel in degrees. Linear axes are left out: their limits are machine coordinates, which a
// program's work coordinates do not give.
struct RotaryLimits {
  char axis = 'A';  // A, B or C
  double min = 0, max = 0;
  toolpath::SourcePosition where;
};

class MachineParameters {
public:
  Units units() const { return units_; }
  const std::string& file_name() const { return file_; }

  // Typed lookups of documented keys (case-insensitive), with the engine default of spec 3.0 when
  // the file does not set the key. Throws std::out_of_range when the key is undocumented, of
  // another kind, or absent without a default.
  bool logical(std::string_view key) const;
  std::int64_t integer(std::string_view key) const;
  double numeric(std::string_view key) const;          // Number keys: the job's unit half
  Eigen::Vector3d point(std::string_view key) const;   // Point keys: the job's unit half
  const std::string& text(std::string_view key) const; // String and Enumeration keys
  // The parameter as written in the file, or nullptr when the file does not set it.
  const Parameter* find(std::string_view key) const;
  // Whether the file sets the key (engine defaults do not count).
  bool has(std::string_view key) const { return find(key) != nullptr; }

  // Every documented scalar key the file sets, in file order.
  const std::vector<Parameter>& parameters() const { return parameters_; }
  // Records of a repeatable key ("drill_type" also returns "drill_type_ger" lines), file order.
  std::vector<const Record*> records(std::string_view key) const;
  const std::vector<Record>& all_records() const { return records_; }
  // The drill record named `name` (the value of `drill_type` in a `@drill`), or nullptr.
  const Record* drill_cycle(std::string_view name) const;

  const std::vector<UnknownKey>& unknown_keys() const { return unknown_; }
  const UnknownKey* unknown(std::string_view key) const;
  const std::vector<Diagnostic>& warnings() const { return warnings_; }

  // PRP external variables, each once, in declaration order.
  const std::vector<ExternalVariable>& external_variables() const { return externals_; }
  // The rotary axes the machine definition limits (a VMID; a PRP says none), each once.
  const std::vector<RotaryLimits>& rotary_limits() const { return rotary_limits_; }

private:
  friend class Loader;
  const Parameter& lookup(std::string_view key, ValueKind kind) const;

  Units units_ = Units::Metric;
  std::string file_;
  std::vector<Parameter> parameters_;
  std::map<std::string, std::size_t, std::less<>> index_;  // lower-case key -> parameters_
  std::vector<Parameter> defaults_;                          // engine defaults, parsed once
  std::map<std::string, std::size_t, std::less<>> default_index_;
  std::vector<Record> records_;
  std::vector<UnknownKey> unknown_;
  std::vector<Diagnostic> warnings_;
  std::vector<ExternalVariable> externals_;
  std::vector<RotaryLimits> rotary_limits_;
};

// Loads a machine file: a PRP (also the pre-2010 `.mac`), or a SolidCAM VMID, which is XML and
// recognised by content (first non-blank character `<`), whatever the name. Throws LoadError with
// every error found (file:line:col), or toolpath::InputError when the file cannot be read.
MachineParameters load_file(const std::string& path, Units units);
MachineParameters load_source(std::string_view text, const std::string& file_name, Units units);
// The parameters of a machine whose PRP sets nothing: every key at its engine default (spec 3.0).
MachineParameters defaults(Units units);

// Canonical PRP text of one value (`Y`/`N` for logicals, shortest exact numbers, `m, i` pairs) and
// of a whole parameter set: loading the written text gives the same parameters, records and
// unknown keys (file positions aside).
std::string format_value(const Parameter& parameter);
std::string format_record(const Record& record);
std::string write_source(const MachineParameters& params);

// Values the engine hands to the post for the time estimate (spec 3.15).
struct TimeSettings {
  double time_factor = 1.0;
  double block_time = 0.0;        // seconds per motion block
  double change_tool_time = 0.0;  // seconds per tool change
  std::optional<double> rapid_feed;  // length/min, job units
  bool calc_job_time = false;
};
TimeSettings time_settings(const MachineParameters& params);

// Program-number limits (spec 2.3, 3.7); each range is checked at load time.
struct NumberRange {
  std::optional<std::int64_t> min, max, dflt;
  bool contains(std::int64_t n) const { return (!min || n >= *min) && (!max || n <= *max); }
};
NumberRange program_numbers(const MachineParameters& params);
NumberRange procedure_numbers(const MachineParameters& params);

// A command the filters cannot process as the PRP asks (a drill cycle that cannot be expanded, a
// malformed @arc, a label beyond proc_num_max). what(): "command N (@name): message", N being the
// command's position in the input stream; the engine puts the toolpath file and the line of the
// command's header (line()) in front.
class StreamError : public std::runtime_error {
public:
  StreamError(const toolpath::Command& command, const std::string& message);
  std::size_t command_index() const { return index_; }
  const std::string& command_name() const { return name_; }
  const std::string& message() const { return message_; }
  std::uint32_t line() const { return line_; }  // the command's header line in the input (0: unknown)

private:
  std::size_t index_;
  std::uint32_t line_;
  std::string name_;
  std::string message_;
};

// Receives the filters' warnings (a stream that does not match the PRP, see docs/prp.md).
using WarningSink = std::function<void(const toolpath::Command& command, const std::string& message)>;

// What a first pass over a job found for procedure generation (gen_procs = Y or C): its main
// program and the jobs' labels, so that the chain can send the main program at once and the bodies
// as the job streams in (docs/prp.md, "Procedures in two passes").
class JobForecast;

// Whether the parameters let procedures be generated in two passes: they ask for procedures, and
// no filter before procedure generation depends on the motions a skim leaves out (mode commands,
// init_cpos, wire guides).
bool two_passes_possible(const MachineParameters& params);

// The first pass, over `skimmed`: the job as toolpath::TraceReader::skim_job_motions() reads it,
// depth 0 and 1 only. nullptr when the job needs one pass (shared drill point lists, a job that stays
// inline, commands after @end_of_file, a toolpath with procedures already) or the skim cannot be
// read (the full pass reports why). Warnings are not given here: the full pass gives them.
std::shared_ptr<JobForecast> forecast_jobs(const MachineParameters& params, toolpath::CommandSource& skimmed);

// Thrown by a chain built with a forecast when the job turns out to differ from it outside the
// bodies (which a skim should never cause): the run must start again without a forecast.
class ForecastMismatch : public std::exception {
public:
  explicit ForecastMismatch(std::string what) : what_(std::move(what)) {}
  const char* what() const noexcept override { return what_.c_str(); }

private:
  std::string what_;
};

// Wires the stream filters the parameters call for, in the order of spec 3.0, around `input`
// (which must outlive the chain). Filters whose parameters ask for nothing are left out. The
// parameters must outlive the chain too. Filters throw StreamError; warnings go to `warn` (dropped
// when empty). With a `forecast` of the same job (forecast_jobs), procedures are generated in its
// second pass.
std::unique_ptr<toolpath::CommandSource> build_filter_chain(const MachineParameters& params,
                                                            toolpath::CommandSource& input,
                                                            WarningSink warn = {},
                                                            std::shared_ptr<JobForecast> forecast = nullptr);

}  // namespace prp
