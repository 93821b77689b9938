// Validation of the symbol/file prefix of generated code (C99 §6.4.2, §7.1.3, §7.26).
#include <algorithm>
#include <cctype>
#include <string>

#include "hinf/codegen/codegen.hpp"
#include "hinf/common/error.hpp"

namespace hinf::codegen {
namespace {

// External identifiers are significant to 31 characters in C99 (§5.2.4.1); the
// longest name generated is PREFIX + "_C_F_pinv" / "_vec_z0", so 22 keeps every name
// within 31.
constexpr std::size_t kMaxPrefixLength = 22;

bool is_keyword(const std::string& s) {
  static const char* const words[] = {
      // C99
      "auto", "break", "case", "char", "const", "continue", "default", "do", "double",
      "else", "enum", "extern", "float", "for", "goto", "if", "inline", "int", "long",
      "register", "restrict", "return", "short", "signed", "sizeof", "static", "struct",
      "switch", "typedef", "union", "unsigned", "void", "volatile", "while", "_Bool",
      "_Complex", "_Imaginary",
      // C++ (the header is meant to be included from C++ as well)
      "alignas", "alignof", "and", "and_eq", "asm", "bitand", "bitor", "bool", "catch",
      "char16_t", "char32_t", "char8_t", "class", "compl", "concept", "consteval",
      "constexpr", "constinit", "const_cast", "co_await", "co_return", "co_yield",
      "decltype", "delete", "dynamic_cast", "explicit", "export", "false", "friend",
      "mutable", "namespace", "new", "noexcept", "not", "not_eq", "nullptr", "operator",
      "or", "or_eq", "private", "protected", "public", "reinterpret_cast", "requires",
      "static_assert", "static_cast", "template", "this", "thread_local", "throw", "true",
      "try", "typeid", "typename", "using", "virtual", "wchar_t", "xor", "xor_eq",
      // the generated driver defines main
      "main"};
  return std::find(std::begin(words), std::end(words), s) != std::end(words);
}

bool starts_with(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

[[noreturn]] void refuse(const std::string& prefix, const std::string& why) {
  throw Error(ErrorCode::InvalidInput, "--prefix '" + prefix + "': " + why);
}

}  // namespace

void validate_codegen_prefix(const std::string& prefix) {
  if (prefix.empty()) refuse(prefix, "must not be empty");
  if (prefix.size() > kMaxPrefixLength)
    refuse(prefix, "too long (" + std::to_string(prefix.size()) + " characters, at most " +
                       std::to_string(kMaxPrefixLength) +
                       " so that every generated external name stays within the 31 "
                       "significant characters C99 guarantees)");
  const auto is_ident_char = [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return (u < 128) && (std::isalnum(u) != 0 || c == '_');
  };
  if (!std::all_of(prefix.begin(), prefix.end(), is_ident_char))
    refuse(prefix, "must be a C identifier: ASCII letters, digits and '_' only");
  if (std::isalpha(static_cast<unsigned char>(prefix[0])) == 0)
    refuse(prefix, "must start with a letter (names starting with a digit are invalid, "
                   "names starting with '_' are reserved)");
  if (prefix.find("__") != std::string::npos)
    refuse(prefix, "must not contain '__' (reserved in C++)");
  if (prefix.back() == '_')
    refuse(prefix, "must not end with '_' (the generated names would contain '__')");
  if (is_keyword(prefix)) refuse(prefix, "is a C or C++ keyword or 'main'");

  // Names reserved for future library use (C99 §7.26). Functions are generated with
  // the prefix as given, macros with the prefix in upper case.
  const std::string& p = prefix;
  const auto lower_at = [&p](std::size_t i) {
    return i < p.size() && std::islower(static_cast<unsigned char>(p[i])) != 0;
  };
  for (const char* r : {"is", "to"})
    if (starts_with(p, r) && lower_at(2))
      refuse(prefix, std::string("names starting with '") + r +
                         "' followed by a lower-case letter are reserved (<ctype.h>)");
  for (const char* r : {"str", "mem", "wcs"})
    if (starts_with(p, r) && lower_at(3))
      refuse(prefix, std::string("names starting with '") + r +
                         "' followed by a lower-case letter are reserved (<string.h>, "
                         "<stdlib.h>, <wchar.h>)");
  // Every generated macro is UPPER + "_" + an upper-case letter (UPPER_NX, ...).
  std::string upper = prefix;
  std::transform(upper.begin(), upper.end(), upper.begin(), [](char c) {
    return static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  });
  const std::string macro = upper + "_N";
  const auto up_or_digit = [](char c) {
    return std::isupper(static_cast<unsigned char>(c)) != 0 ||
           std::isdigit(static_cast<unsigned char>(c)) != 0;
  };
  const auto why_macro = [&upper](const std::string& rule) {
    return "the generated macros " + upper + "_NX, ... " + rule;
  };
  if (macro[0] == 'E' && up_or_digit(macro[1]))
    refuse(prefix, why_macro("start with 'E' and a letter or digit, reserved for <errno.h>"));
  if (starts_with(macro, "SIG") &&
      (std::isupper(static_cast<unsigned char>(macro[3])) != 0 ||
       (macro[3] == '_' && std::isupper(static_cast<unsigned char>(macro[4])) != 0)))
    refuse(prefix, why_macro("start with 'SIG' and a letter or 'SIG_', reserved for <signal.h>"));
  if (starts_with(macro, "LC_") && std::isupper(static_cast<unsigned char>(macro[3])) != 0)
    refuse(prefix, why_macro("start with 'LC_' and a letter, reserved for <locale.h>"));
  if ((starts_with(macro, "PRI") || starts_with(macro, "SCN")) && macro[3] == 'X')
    refuse(prefix, why_macro("start with 'PRIX' or 'SCNX', reserved for <inttypes.h>"));
}

}  // namespace hinf::codegen
