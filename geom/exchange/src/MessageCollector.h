#pragma once
// OpenCASCADE's failure messages, kept for error reports (private to geom_exchange).

#include <Message_Printer.hxx>

#include <string>
#include <vector>

namespace geom::exchange {

/// Collects the messages of gravity Fail and above sent to OpenCASCADE's default messenger, e.g.
/// a STEP file's syntax error and its line. Installed by the reading child process for its life
/// (the messenger holds it by handle).
class MessageCollector : public Message_Printer {
public:
    MessageCollector() { SetTraceLevel(Message_Fail); }

    /// The first failure, or "" when none came.
    std::string first() const { return failures_.empty() ? std::string() : failures_.front(); }

protected:
    void send(const TCollection_AsciiString& text, const Message_Gravity gravity) const override;

private:
    mutable std::vector<std::string> failures_;
};

}  // namespace geom::exchange
