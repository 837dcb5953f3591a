#pragma once
// "did you mean" suggestions for misspelt keys, tables, scenes and parameters.
#include <string>
#include <vector>

namespace sdfreel {

// Edit distance with adjacent transpositions counting as one edit (optimal string alignment).
int edit_distance(const std::string& a, const std::string& b);

// "; did you mean 'x'?" for the closest candidate when it is close enough, otherwise "".
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace sdfreel
