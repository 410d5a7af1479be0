#include "acsynt/ModelList.h"

#include "acsynt/ModelFile.h"

#include <stdexcept>

namespace acsynt {
namespace {

std::string changed(const Model& m) {
    return "MODEL CHANGE COMPLETE.  CURRENT MODEL NAME = " + m.name;
}

}  // namespace

void ModelList::add(Model model) {
    models_.push_back(std::move(model));
    current_ = models_.size() - 1;
}

Model& ModelList::current() {
    if (models_.empty()) throw std::logic_error("ModelList::current: no model is loaded");
    return models_[current_];
}

const Model& ModelList::current() const {
    if (models_.empty()) throw std::logic_error("ModelList::current: no model is loaded");
    return models_[current_];
}

ModelList::Outcome ModelList::next() {
    if (models_.empty()) return {false, "NO GEOMETRY FILE FOUND!"};
    if (current_ + 1 >= models_.size()) return {false, "NEXT MODEL DOES NOT EXIST"};
    ++current_;
    return {true, changed(models_[current_])};
}

ModelList::Outcome ModelList::previous() {
    if (models_.empty()) return {false, "NO GEOMETRY FILE FOUND!"};
    if (current_ == 0) return {false, "PREVIOUS MODEL DOES NOT EXIST"};
    --current_;
    return {true, changed(models_[current_])};
}

ModelList::Outcome ModelList::select(std::size_t index) {
    if (index >= models_.size()) return {false, "BAD INPUT IN MODELS"};
    current_ = index;
    return {true, changed(models_[current_])};
}

std::vector<std::string> ModelList::names() const {
    std::vector<std::string> out;
    out.reserve(models_.size());
    for (const Model& m : models_) out.push_back(m.name);
    return out;
}

std::string ModelList::nameTaken(const std::string& name, std::size_t except) const {
    for (std::size_t i = 0; i < models_.size(); ++i)
        if (i != except && models_[i].name == name)
            return "BAD INPUT IN MODELS: A MODEL NAMED " + name + " IS LOADED (NAMES ARE UNIQUE)";
    return {};
}

ModelList::Outcome ModelList::rename(const std::string& name) {
    if (models_.empty()) return {false, "NO GEOMETRY FILE FOUND!"};
    if (!isValidName(name)) return {false, "BAD INPUT IN MODELS"};
    if (const std::string taken = nameTaken(name, current_); !taken.empty()) return {false, taken};
    models_[current_].name = name;
    return {true, "CURRENT MODEL NAMED " + name};
}

ModelList::Outcome ModelList::removeCurrent() {
    if (models_.empty()) return {false, "NO GEOMETRY FILE FOUND!"};
    const std::string gone = models_[current_].name;
    models_.erase(models_.begin() + static_cast<std::ptrdiff_t>(current_));
    if (models_.empty()) {
        current_ = 0;
        return {true, "MODEL " + gone + " DELETED.  NO MODEL LEFT"};
    }
    if (current_ > 0) --current_;
    return {true, "MODEL " + gone + " DELETED.  CURRENT MODEL NAME = " + models_[current_].name};
}

ModelList::Outcome ModelList::copyCurrent(const std::string& name) {
    if (models_.empty()) return {false, "NO GEOMETRY FILE FOUND!"};
    if (!isValidName(name)) return {false, "BAD INPUT IN MODELS"};
    if (const std::string taken = nameTaken(name, models_.size()); !taken.empty()) return {false, taken};
    Model copy = models_[current_];
    copy.name = name;
    copy.sourceFile.clear();
    models_.push_back(std::move(copy));
    current_ = models_.size() - 1;
    return {true, "MODEL COPIED.  CURRENT MODEL NAME = " + name};
}

}  // namespace acsynt
