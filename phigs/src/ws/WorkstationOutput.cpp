#include "phigs/ws/WorkstationOutput.h"

#include "phigs/ws/Workstation.h"

namespace phigs {

WorkstationOutput::~WorkstationOutput() {
    if (shown_) shown_->outputDestroyed(this);
}

}  // namespace phigs
