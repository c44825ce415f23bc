#include "glint/scene/pov/pov_symbols.h"

namespace glint {

PovSymbols::Table* PovSymbols::holder(std::string_view name) {
    const std::string key(name);
    for (auto it = locals_.rbegin(); it != locals_.rend(); ++it)
        if (it->contains(key)) return &*it;
    return global_.contains(key) ? &global_ : nullptr;
}

void PovSymbols::declare(const std::string& name, PovValue value) {
    Table* table = holder(name);
    (table ? *table : global_)[name] = std::move(value);
}

void PovSymbols::local(const std::string& name, PovValue value) {
    (locals_.empty() ? global_ : locals_.back())[name] = std::move(value);
}

PovValue* PovSymbols::find(std::string_view name) {
    Table* table = holder(name);
    return table ? &table->find(std::string(name))->second : nullptr;
}

bool PovSymbols::undef(std::string_view name) {
    Table* table = holder(name);
    return table && table->erase(std::string(name)) > 0;
}

}  // namespace glint
