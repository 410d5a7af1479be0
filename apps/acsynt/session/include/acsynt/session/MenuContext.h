#pragma once

#include "acsynt/session/SessionCore.h"

#include <string>

namespace acsynt {

struct MenuTable;

/// What a menu command may do to the session: its state (the core) and the few screen and
/// model operations the commands share; the session implements it.
class MenuContext {
public:
    virtual ~MenuContext() = default;
    virtual SessionCore& core() = 0;
    virtual void say(const std::string& text) = 0;   ///< the message line (and log)
    virtual void fail(const std::string& text) = 0;  ///< an error on the message line
    /// Asks for a line of text (STRING 1); its answer goes to what `what` names.
    virtual void prompt(const std::string& text, SessionCore::Awaiting what) = 0;
    /// True when a model is loaded, else fails with NO GEOMETRY FILE FOUND!.
    virtual bool requireModel() = 0;
    virtual void openMenu(const MenuTable& menu) = 0;  ///< shows `menu` on the panel (CHOICE 1)
    virtual void restyle() = 0;                        ///< redraws the current model in core().style
    virtual void showModel() = 0;  ///< rebuilds the model structures after the current model changed
    virtual void updateViews() = 0;
    virtual void drawOverlay() = 0;         ///< marker, tangents, placed curve, preview lines
    virtual void drawMapped(bool all) = 0;  ///< the current model's mapped curves (all, or the last)
    virtual void drawErrorMap() = 0;
    /// MAP CURVE, or (previewOnly) MAP PREVIEW's projection lines.
    virtual void mapCurve(bool previewOnly) = 0;
    virtual void undo() = 0;
    virtual void redo() = 0;
};

}  // namespace acsynt
