// rupture/input/parameters.hpp
// Named parameters of a case (docs/input.md, "[parameters]"): a [parameters] table of numbers
// (or '='-expressions of the others, in any order, no circles), and any string value of the case that begins with '=' is an arithmetic expression of them,
// replaced by its value before the case is read, so one `--set parameters.NAME=VALUE` moves
// every quantity that depends on it (a notch's offset as a fraction of the span, say).
//   expression := term {('+' | '-') term};  term := factor {('*' | '/') factor}
//   factor := ('+' | '-') factor | primary ['^' factor]
//   primary := number | NAME | pi | FUNC '(' expression ')' | '(' expression ')'
//   FUNC: sqrt, sin, cos, tan, atan, exp, log (natural), abs
// A result that is a whole number (|v| < 2^53), or within 1e-9 of one and at least 1 (round-off:
// 0.019 / 1e-3), becomes a TOML integer (so integer keys such as segments take it), anything
// else a float; a non-finite result, an unknown name, a syntax
// error or nesting deeper than 64 is an InputError naming the key, the expression and the
// reason. The title is left as written. Internal to input/.
#pragma once
#include <map>
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace rupture {

// The value of `text` (without the leading '='), or throws InputError through fail(key, ...).
double evaluate_expression(std::string_view text, const std::map<std::string, double>& names,
                           const std::string& key);

// Reads root's [parameters] (each a finite number, or an expression of the others) and replaces every '='-string elsewhere in
// root (except title) by its value.
void substitute_parameters(toml::table& root);

}  // namespace rupture
