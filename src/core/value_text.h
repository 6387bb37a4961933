// Values quoted in messages, and value-count checks of vector attributes.
#pragma once

#include <string>
#include <string_view>

namespace sinew {

class BaseField;

// A value quoted in a message, in double quotes: values longer than 80
// characters are cut, "\"<first 80>…\" (N characters)", so that a 50 MB
// attribute never makes a 50 MB message.
std::string quote_value(std::string_view v);

// What is wrong with the number of values in `text` for `f`, or "" when
// nothing is: a Vec3d needs exactly 3 values, a list of Vec3d a multiple of
// 3, a list of edges a multiple of 2 ("expected 3 values (Vec3d), got 2").
std::string value_count_problem(const BaseField& f, std::string_view text);

}  // namespace sinew
