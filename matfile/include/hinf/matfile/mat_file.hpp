// MATLAB files (level 5, as MATLAB's `load` and Octave read them) of what the tools write,
// through matio (Debian libmatio): the gains and controller files (`hinf-synth solve
// --format mat`), hinf-sim's run directory (`--format mat`: run.mat). docs/file-formats.md
// "MATLAB files".
//
// A file's variables are given as a JSON object — the same tree as the tools' JSON
// (synth/api.hpp outcomes' `json`, summary.json) — so that the names in MATLAB are the
// names in YAML and JSON: an object is a 1×1 struct (fields in order), an array of equal-
// length arrays of numbers an R×C double matrix (rows as written), an array of numbers a
// 1×N row, a number a double (integers too), a boolean a logical, a string a char row, null
// [] (0×0 double), any other array a 1×N cell. Doubles are stored as they are: read back
// bit for bit (NaN, ±Inf included).
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace hinf::matfile {

using Json = nlohmann::ordered_json;

// The bytes of the MAT-file (uncompressed, deterministic: `description` is the header's
// text, no date) holding each key of `variables` as a variable of that name.
// Error(InvalidInput) naming a key that is not a MATLAB identifier (letters, digits,
// underscores, a letter first, at most 63 characters); Error(NumericalFailure) if matio
// cannot write.
std::string mat_file_bytes(const Json& variables, const std::string& description);

// A CSV table as a struct of N×1 columns named by its header row: a column of numbers
// (an empty cell or "nan" is NaN) a double column, any other column an N×1 cell of
// strings. Header names that are not identifiers have every other character replaced by
// '_' (and 'x' before a leading digit). Error(InvalidInput) on a ragged row.
Json csv_columns(const std::string& csv_text, const std::string& name);

}  // namespace hinf::matfile
