// The identifiers of a POV-Ray scene: one global table and a stack of local ones (an include
// file's and each macro call's), as POV-Ray scopes #declare and #local.
#pragma once

#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "glint/scene/pov/pov_value.h"

namespace glint {

class PovSymbols {
public:
    void push_scope() { locals_.emplace_back(); }
    void pop_scope() { locals_.pop_back(); }
    std::size_t depth() const { return locals_.size(); }

    // #declare: the innermost table that holds the name, else the global one.
    void declare(const std::string& name, PovValue value);
    // #local: the innermost table (the global one outside includes and macros).
    void local(const std::string& name, PovValue value);
    // The innermost value of the name; null when it is not declared.
    PovValue* find(std::string_view name);
    // #undef: removes the innermost; false when it was not declared.
    bool undef(std::string_view name);

private:
    using Table = std::unordered_map<std::string, PovValue>;
    Table* holder(std::string_view name);

    Table global_;
    std::vector<Table> locals_;
};

}  // namespace glint
