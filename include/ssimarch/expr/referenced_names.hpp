// The names an expression mentions, without compiling it: lets a scene order its constants by
// dependency before evaluating them (io/scene.cpp; linear, where evaluating by trial passes was cubic).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace ssimarch {

/// The names `source` mentions (variables, constants, functions), in order of appearance, without
/// repeats. Lexing stops quietly at the first bad character (compiling reports it).
std::vector<std::string> referenced_names(std::string_view source);

}  // namespace ssimarch
