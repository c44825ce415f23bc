// Numbers as validation messages show them: the shortest general form ("1", "0.001", "1e+06").
#pragma once

#include <sstream>
#include <string>

namespace glint {

inline std::string number_text(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

}  // namespace glint
