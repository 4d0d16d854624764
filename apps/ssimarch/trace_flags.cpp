#include "trace_flags.hpp"

#include <algorithm>

namespace ssimarch::cli {

void add_trace_option_flags(CLI::App* cmd, TraceOptionFlags* flags) {
  const auto& table = trace_option_table();
  flags->values.resize(table.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    const TraceOptionSpec& o = table[i];
    std::string help =
        std::string(o.help) + " (overrides the scene; " + o.rule + "; default " + std::string(o.default_text) + ")";
    CLI::Option* flag = cmd->add_option(o.flag(), flags->values[i], help);
    flag->type_name(o.type == TraceOptionSpec::Type::kChoice ? "NAME" : "VALUE");
    flags->flags.emplace_back(&o, flag);
  }
}

std::vector<OptionOverride> trace_overrides(const TraceOptionFlags& flags) {
  std::vector<OptionOverride> out;
  for (std::size_t i = 0; i < flags.flags.size(); ++i) {
    const auto& [spec, flag] = flags.flags[i];
    if (flag->count() > 0) out.push_back({spec, flags.values[i], spec->flag()});
  }
  return out;
}

void add_format_overrides(OutputFormat format, TraceRequest* request) {
  auto set = [&](const char* key) {
    const TraceOptionSpec* spec = find_trace_option(key);
    return std::any_of(request->overrides.begin(), request->overrides.end(),
                       [&](const OptionOverride& o) { return o.option == spec; });
  };
  if (format == OutputFormat::kStep && !set("bspline"))
    request->overrides.push_back({find_trace_option("bspline"), std::string("true"), "--format step"});
  if ((format == OutputFormat::kVtp || format == OutputFormat::kVtpAscii) && !set("geometry"))
    request->overrides.push_back({find_trace_option("geometry"), std::string("mixed"), "--format vtp"});
}

}  // namespace ssimarch::cli
