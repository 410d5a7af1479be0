#pragma once

#include "acsynt/Model.h"

#include <cstddef>
#include <string>
#include <vector>

namespace acsynt {

/// ACSYNT's MODELS menu as plain data: the models in memory in order (an original and its
/// reduced versions), one of them current. Each operation answers with the message-line text.
class ModelList {
public:
    /// What an operation did and the message ACSYNT shows for it.
    struct Outcome {
        bool done = false;
        std::string message;
    };

    /// Appends a model (FILE → READ MODEL) and makes it current.
    void add(Model model);

    bool empty() const { return models_.empty(); }
    std::size_t size() const { return models_.size(); }
    std::size_t currentIndex() const { return current_; }
    /// The current model; throws std::logic_error when the list is empty.
    Model& current();
    const Model& current() const;
    const Model& at(std::size_t index) const { return models_.at(index); }

    Outcome next();      ///< NEXT MODEL
    Outcome previous();  ///< PREVIOUS MODEL
    /// Makes the model at `index` current (a pick in the LIST window).
    Outcome select(std::size_t index);
    /// LIST: the names in order.
    std::vector<std::string> names() const;
    /// Whether a loaded model is named `name`.
    bool contains(const std::string& name) const { return nameTaken(name, models_.size()).size() > 0; }
    /// NAME MODEL: 1 to 20 letters, digits, '_', '-', '.', not another loaded model's name;
    /// anything else leaves the name unchanged.
    Outcome rename(const std::string& name);
    /// Deletes the current model; its predecessor becomes current (its successor if it was first).
    Outcome removeCurrent();
    /// Appends a copy of the current model under `name` and makes the copy current, for a
    /// reduced version to be worked on while the original stays in the list (a name not loaded).
    Outcome copyCurrent(const std::string& name);

private:
    /// The refusal when a model other than the one at `except` is named `name`, else empty.
    std::string nameTaken(const std::string& name, std::size_t except) const;

    std::vector<Model> models_;
    std::size_t current_ = 0;
};

}  // namespace acsynt
