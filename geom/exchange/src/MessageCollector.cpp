#include "MessageCollector.h"

#include <TCollection_AsciiString.hxx>

namespace geom::exchange {

void MessageCollector::send(const TCollection_AsciiString& text, const Message_Gravity gravity) const {
    if (gravity < Message_Fail || failures_.size() >= 16) return;
    std::string line = text.ToCString();
    while (!line.empty() && (line.back() == '\n' || line.back() == ' ' || line.back() == '*'))
        line.pop_back();
    while (!line.empty() && (line.front() == ' ' || line.front() == '*')) line.erase(line.begin());
    if (line.rfind("ERR ", 0) == 0) line.erase(0, 4);
    if (!line.empty()) failures_.push_back(line);
}

}  // namespace geom::exchange
