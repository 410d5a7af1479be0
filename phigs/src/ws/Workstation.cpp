#include "phigs/ws/Workstation.h"

#include <algorithm>
#include <cmath>

namespace phigs {
namespace {

/// The smallest string echo area that holds a line of text, in pixels: smaller ones (the
/// default 1 x 1) echo nothing.
constexpr double minimumEchoLine = 8.0;

}  // namespace

Workstation::Workstation(int id, WorkstationType type, StructureStore& store, ErrorLog* log)
    : id_(id),
      description_(describeWorkstationType(type)),
      store_(store),
      log_(log),
      measurer_([this]() -> const DrawList& { return display(); }),
      input_(std::make_unique<WorkstationInput>(id, measurer_, description_.inputDevices)) {
    tables_.views = ViewTable(description_.viewTableSize);
    tables_.colours = ColourTable(description_.colourTableSize);
    tables_.viewportMax = {description_.displaySize.x, description_.displaySize.y, 1.0};
    tables_.displaySize = description_.displaySize;
    measurer_.setSurfaceSize([this] {
        const DrawableSize size = drawableSize();
        if (size.width > 0 && size.height > 0) return DrawListMeasurer::SurfaceSize{size.width, size.height};
        const glm::dvec2 display = description_.displaySize;  // minimised: no pixels to map
        return DrawListMeasurer::SurfaceSize{std::uint32_t(std::lround(display.x)),
                                             std::uint32_t(std::lround(display.y))};
    });
    measurer_.setPickListProvider(
        [this](const InputDevice& device) -> const DrawList& { return pickList(device); });
    input_->setEchoListener([this] { echoMoved(); });
    store_.addListener(this);
}

Workstation::~Workstation() {
    input_.reset();        // leaves the input queue before anything else goes
    ownedOutput_.reset();  // an output may detach itself from the workstation as it goes
    store_.removeListener(this);
}

void Workstation::ownOutput(std::unique_ptr<WorkstationOutput> output) {
    ownedOutput_ = std::move(output);
    output_ = ownedOutput_.get();
}

void Workstation::closeOutput() {
    if (output_) output_->close(shownPicture());
}

void Workstation::postStructure(int structureId, double priority) {
    if (!(priority >= 0.0 && priority <= 1.0))
        raise(log_, errors::BadDisplayPriority, "POST STRUCTURE", "priority " + std::to_string(priority));
    store_.createStructure(structureId);
    std::erase_if(posted_, [&](const PostedStructure& p) { return p.structureId == structureId; });
    posted_.push_back({structureId, priority});
    changed();
}

void Workstation::unpostStructure(int structureId) {
    if (std::erase_if(posted_, [&](const PostedStructure& p) { return p.structureId == structureId; }))
        changed();
}

void Workstation::unpostAllStructures() {
    if (!posted_.empty()) changed();
    posted_.clear();
}

std::vector<PostedStructure> Workstation::postedStructures() const {
    std::vector<PostedStructure> order = posted_;
    std::stable_sort(order.begin(), order.end(), [](const PostedStructure& a, const PostedStructure& b) {
        return a.priority < b.priority;
    });
    return order;
}

bool Workstation::isPosted(int structureId) const {
    return std::any_of(posted_.begin(), posted_.end(),
                       [&](const PostedStructure& p) { return p.structureId == structureId; });
}

void Workstation::structureDeleted(int structureId) {
    unpostStructure(structureId);
}

void Workstation::referencesChanged(int from, int to) {
    auto it = std::find_if(posted_.begin(), posted_.end(),
                           [&](const PostedStructure& p) { return p.structureId == from; });
    if (it == posted_.end()) return;
    double priority = it->priority;
    posted_.erase(it);
    if (!isPosted(to)) posted_.push_back({to, priority});
    changed();
}

void Workstation::setDeferralState(DeferralMode deferral, ModificationMode modification) {
    deferral_ = deferral;
    modification_ = modification;
}

bool Workstation::showsChangesAtOnce() const {
    // No interaction is ever "underway" between calls here, so BNIG and BNIL behave as ASAP.
    return deferral_ == DeferralMode::Asap || deferral_ == DeferralMode::Bnig ||
           deferral_ == DeferralMode::Bnil;
}

std::uint64_t Workstation::contentStamp() const {
    // Every edit of the store counts an operation and every table or posting change a table
    // generation: with neither, the networks and their versions are those of the last stamp.
    if (stamped_ && stampOperations_ == store_.operationCount() && stampTables_ == tables_.generation)
        return stamp_;
    std::uint64_t hash = 1469598103934665603ull;
    auto mix = [&](std::uint64_t v) { hash = (hash ^ v) * 1099511628211ull; };
    mix(tables_.generation);
    for (const PostedStructure& p : posted_) mix(store_.networkStamp(p.structureId));
    stamp_ = hash;
    stampOperations_ = store_.operationCount();
    stampTables_ = tables_.generation;
    stamped_ = true;
    return hash;
}

VisualState Workstation::visualState() const {
    if (!pictured_ || contentStamp() != pictureStamp_)
        return showsChangesAtOnce() ? VisualState::Correct
                                    : (modification_ == ModificationMode::Nive ? VisualState::Deferred
                                                                               : VisualState::Simulated);
    return pictureState_;
}

void Workstation::regenerate(VisualState after) {
    std::uint64_t stamp = contentStamp();
    std::vector<int> roots;
    for (const PostedStructure& p : postedStructures()) roots.push_back(p.structureId);
    std::uint64_t generation = picture_.generation;
    bool same = pictured_ && stamp == pictureStamp_;
    // The old items go first, so a regeneration never holds two pictures (the traverser keeps
    // what it reuses); a traversal that throws leaves no picture and a new generation.
    picture_.items.clear();
    picture_.generation = generation + 1;
    pictured_ = false;
    picture_ = traverser_.traverse(store_, roots, tables_, filters_);
    picture_.generation = same ? generation : generation + 1;
    pictureStamp_ = stamp;
    pictured_ = true;
    pictureState_ = after;
    ++regenerations_;
}

void Workstation::update(Regeneration regeneration) {
    if (regeneration == Regeneration::Perform &&
        (!pictured_ || contentStamp() != pictureStamp_ || pictureState_ != VisualState::Correct))
        regenerate(VisualState::Correct);
}

void Workstation::redrawAllStructures() {
    regenerate(VisualState::Correct);
}

const DrawList& Workstation::display() {
    if (!pictured_ || contentStamp() != pictureStamp_) {
        if (showsChangesAtOnce())
            regenerate(VisualState::Correct);
        else if (modification_ != ModificationMode::Nive)
            regenerate(VisualState::Simulated);
        else if (!pictured_)
            regenerate(VisualState::Correct);
    }
    // Input priority is no part of the picture: it changes nothing drawn and needs no traversal.
    picture_.viewInputPriority = tables_.views.inputPriority();
    return picture_;
}

DrawList Workstation::traverse(const TraversalFilters& filters) {
    std::vector<int> roots;
    for (const PostedStructure& p : postedStructures()) roots.push_back(p.structureId);
    return traverser_.traverse(store_, roots, tables_, filters);
}

void Workstation::setColourRepresentation(int index, const glm::dvec3& rgb) {
    tables_.colours.set(index, rgb, log_);
    changed();
}

namespace {

void checkLineType(LineType t, ErrorLog* log, const char* function) {
    if (static_cast<int>(t) < 1 || static_cast<int>(t) > 4) raise(log, errors::BadLineType, function);
}

}  // namespace

void Workstation::setPolylineRepresentation(int index, const PolylineBundle& bundle) {
    const char* function = "SET POLYLINE REPRESENTATION";
    checkLineType(bundle.type, log_, function);
    tables_.polylines.set(index, bundle, log_, function);
    changed();
}

void Workstation::setPolymarkerRepresentation(int index, const PolymarkerBundle& bundle) {
    const char* function = "SET POLYMARKER REPRESENTATION";
    if (static_cast<int>(bundle.type) < 1 || static_cast<int>(bundle.type) > 5)
        raise(log_, errors::BadMarkerType, function);
    tables_.polymarkers.set(index, bundle, log_, function);
    changed();
}

void Workstation::setTextRepresentation(int index, const TextBundle& bundle) {
    tables_.texts.set(index, bundle, log_, "SET TEXT REPRESENTATION");
    changed();
}

void Workstation::setInteriorRepresentation(int index, const InteriorBundle& bundle) {
    const char* function = "SET INTERIOR REPRESENTATION";
    if (static_cast<int>(bundle.style) < 0 || static_cast<int>(bundle.style) > 4)
        raise(log_, errors::BadInteriorStyle, function);
    tables_.interiors.set(index, bundle, log_, function);
    changed();
}

void Workstation::setEdgeRepresentation(int index, const EdgeBundle& bundle) {
    const char* function = "SET EDGE REPRESENTATION";
    checkLineType(bundle.type, log_, function);
    tables_.edges.set(index, bundle, log_, function);
    changed();
}

void Workstation::setViewRepresentation(int index, const ViewRepresentation& view) {
    tables_.views.set(index, view, log_);
    changed();
}

void Workstation::setViewTransformationInputPriority(int index, int reference, bool higher) {
    tables_.views.setInputPriority(index, reference, higher, log_);
}

void Workstation::setLightSourceRepresentation(int index, const Light& light) {
    const char* function = "SET LIGHT SOURCE REPRESENTATION";
    if (index < 1) raise(log_, errors::BundleIndexBelowOne, function, "index " + std::to_string(index));
    if (!tables_.lights.contains(index) &&
        static_cast<int>(tables_.lights.size()) >= description_.lightTableSize)
        raise(log_, errors::BundleTableFull, function, "index " + std::to_string(index));
    tables_.lights[index] = light;
    changed();
}

void Workstation::setDepthCueRepresentation(int index, const DepthCue& cue) {
    const char* function = "SET DEPTH CUE REPRESENTATION";
    if (index < 1) raise(log_, errors::BundleIndexBelowOne, function, "index " + std::to_string(index));
    if (!tables_.depthCues.contains(index) &&
        static_cast<int>(tables_.depthCues.size()) >= description_.depthCueTableSize)
        raise(log_, errors::BundleTableFull, function, "index " + std::to_string(index));
    tables_.depthCues[index] = cue;
    changed();
}

void Workstation::setHlhsrMode(int mode) {
    const auto& modes = description_.hlhsrModes;
    if (std::find(modes.begin(), modes.end(), mode) == modes.end())
        raise(log_, errors::BadHlhsrMode, "SET HLHSR MODE", "mode " + std::to_string(mode));
    tables_.hlhsrMode = mode;
    changed();
}

void Workstation::setWorkstationWindow(const glm::dvec3& min, const glm::dvec3& max) {
    const char* function = "SET WORKSTATION WINDOW 3";
    if (min.x >= max.x || min.y >= max.y || min.z > max.z) raise(log_, errors::InvalidWindow, function);
    for (int i = 0; i < 3; ++i)
        if (min[i] < 0.0 || max[i] > 1.0) raise(log_, errors::WorkstationWindowOutsideNpc, function);
    tables_.windowMin = min;
    tables_.windowMax = max;
    changed();
}

void Workstation::setWorkstationViewport(const glm::dvec3& min, const glm::dvec3& max) {
    const char* function = "SET WORKSTATION VIEWPORT 3";
    if (min.x >= max.x || min.y >= max.y || min.z > max.z) raise(log_, errors::InvalidViewport, function);
    glm::dvec3 limit{description_.displaySize.x, description_.displaySize.y, 1.0};
    for (int i = 0; i < 3; ++i)
        if (min[i] < 0.0 || max[i] > limit[i])
            raise(log_, errors::WorkstationViewportOutsideDisplay, function);
    tables_.viewportMin = min;
    tables_.viewportMax = max;
    changed();
}

void Workstation::setDisplaySize(glm::dvec2 size) {
    if (!(size.x > 0.0 && size.y > 0.0))
        raise(log_, errors::InvalidViewport, "SET DISPLAY SIZE",
              std::to_string(size.x) + " x " + std::to_string(size.y) + " device units");
    if (size == description_.displaySize) return;
    const glm::dvec2 old = description_.displaySize;
    const bool whole = tables_.viewportMin.x == 0.0 && tables_.viewportMin.y == 0.0 &&
                       tables_.viewportMax.x == old.x && tables_.viewportMax.y == old.y;
    description_.displaySize = size;
    tables_.displaySize = size;
    if (whole) tables_.viewportMax = {size.x, size.y, tables_.viewportMax.z};
    changed();
}

const DrawList& Workstation::shownPicture() {
    const DrawList& picture = display();
    if (echo_.empty()) return picture;
    echoed_ = picture;
    for (DrawItem& item : echoed_.items)
        if (std::find(echo_.begin(), echo_.end(), item.source.path) != echo_.end()) item.highlighted = true;
    return echoed_;
}

bool Workstation::present() {
    if (!output_) return false;
    shownEcho_ = echoState();
    output_->showEcho(shownEcho_);
    return output_->present(shownPicture());
}

void Workstation::echoMoved() {
    if (output_ && echoState() != shownEcho_) present();
}

const DrawList& Workstation::pickList(const InputDevice& device) {
    TraversalFilters filters = filters_;
    filters.pick = NameSetFilter{device.pickInclusion, device.pickExclusion};
    PickList& cached = pickLists_[device.number];
    lastPickList_ = &cached.list;
    const std::uint64_t stamp = contentStamp();
    // Nothing the traversal reads changed: the list, its generation and the Picker's tree stay.
    if (cached.made && cached.stamp == stamp && cached.filters == filters) return cached.list;
    cached.list = traverse(filters);
    // A new generation per traversal lets the Picker drop intersectors of deleted surfaces.
    cached.list.generation = ++pickTraversals_;
    cached.filters = std::move(filters);
    cached.stamp = stamp;
    cached.made = true;
    return cached.list;
}

std::vector<std::vector<DrawPathLevel>> Workstation::lastPickEcho() const {
    std::vector<std::vector<DrawPathLevel>> paths;
    if (!lastPickList_) return paths;
    for (std::size_t i : measurer_.lastEcho()) paths.push_back(lastPickList_->items.at(i).source.path);
    return paths;
}

EchoState Workstation::echoState() const {
    EchoState state;
    const StringEcho typed = input_->stringEcho();
    if (typed.text.empty() && !typed.cancelled) return state;
    // A window types into string device 1 (WindowEventMapper), the one that can echo it.
    if (input_->counts().string < 1) return state;
    const InputDevice& d = input_->device(InputClass::String, 1);
    const EchoVolume& a = d.setup.echoVolume;
    const bool active = d.mode != OperatingMode::Request || input_->requested() == &d;
    if (d.echo != EchoSwitch::Echo || d.setup.promptEchoType != 1 || !active) return state;
    if (!(a.ymax - a.ymin >= minimumEchoLine && a.xmax - a.xmin >= a.ymax - a.ymin)) return state;
    state.strings.push_back({1, a, typed.text, typed.cancelled});
    return state;
}

DrawableSize Workstation::drawableSize() const {
    if (output_) return output_->drawableSize();
    return {static_cast<std::uint32_t>(std::lround(description_.displaySize.x)),
            static_cast<std::uint32_t>(std::lround(description_.displaySize.y))};
}

void Workstation::setHighlightingFilter(const NameSetFilter& filter) {
    filters_.highlight = filter;
    changed();
}

void Workstation::setInvisibilityFilter(const NameSetFilter& filter) {
    filters_.invisibility = filter;
    changed();
}

void Workstation::setPickFilter(std::optional<NameSetFilter> filter) {
    filters_.pick = std::move(filter);
    changed();
}

}  // namespace phigs
