// How far apart two spellings are, for "did you mean ...?" hints: of unknown scene keys
// (scene/json_reader.h) and of unknown command-line options (app/options.cpp).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace clr {

// Levenshtein distance: the fewest single-character insertions, deletions and substitutions
// that turn one string into the other. Case-sensitive.
std::size_t edit_distance(const std::string& a, const std::string& b);

// The candidate closest to `word`, ignoring case, when it is close enough to be a typo: one
// edit for words of up to 4 characters, two for longer ones. Empty when none is. Candidates
// whose length differs by more than that are never compared letter by letter, so that a
// megabyte-long word costs nothing.
std::string closest_spelling(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace clr
