#include "phigs/ws/Workstation.h"

#include "phigs/ws/PredefinedRepresentations.h"
#include "phigs/ws/WorkstationErrors.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace phigs {
namespace {

/// The smallest string echo area that holds a line of text, in pixels: smaller ones (the
/// default 1 x 1) echo nothing.
constexpr double minimumEchoLine = 8.0;

bool sameView(const ViewRepresentation& a, const ViewRepresentation& b) {
    return a.orientation == b.orientation && a.mapping == b.mapping && a.clipMin == b.clipMin &&
           a.clipMax == b.clipMax && a.clipXY == b.clipXY && a.clipBack == b.clipBack &&
           a.clipFront == b.clipFront;
}

/// The description's predefined representations, loaded into a new workstation's tables.
void loadPredefined(WorkstationTables& t, PatternTable& patterns, WorkstationType type) {
    const PredefinedRepresentations& p = predefinedRepresentations(type);
    const char* function = "OPEN WORKSTATION";
    for (std::size_t i = 0; i < p.polylines.size(); ++i)
        t.polylines.set(int(i) + 1, p.polylines[i], nullptr, function);
    for (std::size_t i = 0; i < p.polymarkers.size(); ++i)
        t.polymarkers.set(int(i) + 1, p.polymarkers[i], nullptr, function);
    for (std::size_t i = 0; i < p.texts.size(); ++i) t.texts.set(int(i) + 1, p.texts[i], nullptr, function);
    for (std::size_t i = 0; i < p.interiors.size(); ++i)
        t.interiors.set(int(i) + 1, p.interiors[i], nullptr, function);
    for (std::size_t i = 0; i < p.edges.size(); ++i) t.edges.set(int(i) + 1, p.edges[i], nullptr, function);
    for (std::size_t i = 0; i < p.patterns.size(); ++i) patterns.set(int(i) + 1, p.patterns[i], nullptr);
}

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
    tables_.limits = description_.primitives;
    patterns_ = PatternTable(description_.patternTableSize);
    loadPredefined(tables_, patterns_, description_.type);
    deferral_ = description_.defaultDeferral;
    modification_ = description_.defaultModification;
    commitCurrent();
    measurer_.setSurfaceSize([this] {
        // An operator's action maps through the picture it was made on (a window resized since).
        if (const auto& at = input_->measuredActionSurface())
            return DrawListMeasurer::SurfaceSize{at->x, at->y};
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
    pictureStamp_ = contentStamp();  // the empty display surface of a new workstation is correct
}

Workstation::~Workstation() {
    if (output_) output_->shown_ = nullptr;  // an output that outlives it leaves it alone
    output_ = nullptr;
    input_.reset();        // leaves the input queue before anything else goes
    ownedOutput_.reset();  // an output may detach itself from the workstation as it goes
    store_.removeListener(this);
}

void Workstation::ownOutput(std::unique_ptr<WorkstationOutput> output) {
    ownedOutput_ = std::move(output);
    attachOutput(ownedOutput_.get());
}

void Workstation::attachOutput(WorkstationOutput* output) {
    if (output_) output_->shown_ = nullptr;
    output_ = output ? output : ownedOutput_.get();
    if (output_) output_->shown_ = this;
}

void Workstation::outputDestroyed(WorkstationOutput* output) {
    output->shown_ = nullptr;
    if (output_ != output) return;
    output_ = nullptr;
    if (ownedOutput_.get() != output) attachOutput(nullptr);
}

void Workstation::closeOutput() {
    if (!output_) return;
    // CLOSE WORKSTATION updates the workstation first; where that fails (a network grown past a
    // limit since), the output still gets the picture it had, and the failure is reported.
    try {
        update(Regeneration::Perform);
    } catch (...) {
        if (pictured_) output_->close(picture_);
        throw;
    }
    output_->close(shownPicture());
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
    // What the old mode showed at once (ASAP, BNIG, BNIL) or simulated at once (UQUM) is on the
    // display; the picture, made lazily when drawn, catches up before a mode that defers reads it
    // as what the display shows.
    if (changesTakeEffectAtOnce() && contentStamp() != pictureStamp_) {
        try {
            regenerate(showsChangesAtOnce() ? VisualState::Correct : VisualState::Simulated);
        } catch (const Error&) {
            // A network the traversal refuses (too deep) is reported when it is drawn, not here:
            // SET DISPLAY UPDATE STATE has no such error.
        }
    }
    deferral_ = deferral;
    modification_ = modification;
    if (changesTakeEffectAtOnce()) commitCurrent();  // the deferred actions are performed now
}

void Workstation::changed() {
    ++tables_.generation;
    if (changesTakeEffectAtOnce()) commitCurrent();
}

bool Workstation::changesTakeEffectAtOnce() const {
    return showsChangesAtOnce() || modification_ == ModificationMode::Uqum;  // UQUM: simulated at once
}

void Workstation::commitCurrent() {
    current_.views = tables_.views;
    current_.windowMin = tables_.windowMin;
    current_.windowMax = tables_.windowMax;
    current_.viewportMin = tables_.viewportMin;
    current_.viewportMax = tables_.viewportMax;
    current_.hlhsrMode = tables_.hlhsrMode;
}

bool Workstation::viewUpdatePending(int index) const {
    return current_.views.defined(index) != tables_.views.defined(index) ||
           !sameView(current_.views.get(index), tables_.views.get(index));
}

bool Workstation::transformationUpdatePending() const {
    return current_.windowMin != tables_.windowMin || current_.windowMax != tables_.windowMax ||
           current_.viewportMin != tables_.viewportMin || current_.viewportMax != tables_.viewportMax;
}

bool Workstation::hlhsrUpdatePending() const {
    return current_.hlhsrMode != tables_.hlhsrMode;
}

bool Workstation::surfaceEmpty() const {
    // Deferring, the display shows the last picture made (at first the empty surface).
    return changesTakeEffectAtOnce() ? posted_.empty() : picturedEmpty_;
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
    if (showsChangesAtOnce()) return VisualState::Correct;  // display() regenerates first
    if (contentStamp() != pictureStamp_)
        return modification_ == ModificationMode::Uqum ? VisualState::Simulated : VisualState::Deferred;
    return pictureState_;
}

namespace {

/// A draw list generation no other list a workstation made in this process has: a picker keeps
/// its bounds tree per list and generation, and two workstations' lists (or one list copied over
/// another, which keeps its storage) must never look alike.
std::uint64_t newGeneration() {
    static std::atomic<std::uint64_t> last{0};
    return ++last;
}

}  // namespace

void Workstation::regenerate(VisualState after) {
    std::uint64_t stamp = contentStamp();
    std::vector<int> roots;
    for (const PostedStructure& p : postedStructures()) roots.push_back(p.structureId);
    std::uint64_t generation = picture_.generation;
    bool same = pictured_ && stamp == pictureStamp_;
    // The old items go first, so a regeneration never holds two pictures (the traverser keeps
    // what it reuses); a traversal that throws leaves no picture and a new generation.
    picture_.items.clear();
    picture_.generation = newGeneration();
    pictured_ = false;
    picture_ = traverser_.traverse(store_, roots, tables_, filters_);
    picture_.patterns = resolvedPatterns();
    picture_.generation = same ? generation : newGeneration();
    pictureStamp_ = stamp;
    pictured_ = true;
    picturedEmpty_ = roots.empty();
    pictureTables_ = tables_;
    commitCurrent();
    pictureState_ = after;
    ++regenerations_;
}

std::map<int, DrawPattern> Workstation::resolvedPatterns() const {
    std::map<int, DrawPattern> out;
    for (int index : patterns_.definedIndices()) {
        const PatternRepresentation& p = *patterns_.find(index);
        DrawPattern& d = out[index];
        d.columns = p.columns;
        d.rows = p.rows;
        d.colours.clear();
        // Indexed cells through the colour table as it is now; direct cells (PHIGS PLUS) as given.
        for (const Colour& c : p.colours) d.colours.push_back(glm::vec3(tables_.colours.resolve(c)));
    }
    return out;
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
    const bool stale = contentStamp() != pictureStamp_;
    if (showsChangesAtOnce()) {
        if (!pictured_ || stale || pictureState_ != VisualState::Correct) regenerate(VisualState::Correct);
    } else if (stale && modification_ == ModificationMode::Uqum) {
        regenerate(VisualState::Simulated);
    } else if (!pictured_) {
        regenerate(VisualState::Correct);  // the first picture is always made
    }
    // Input priority is no part of the picture: it changes nothing drawn and needs no traversal.
    picture_.viewInputPriority = tables_.views.inputPriority();
    return picture_;
}

bool Workstation::picksShownTables() const {
    // A deferred change is not on the display yet: pick what is shown.
    return !changesTakeEffectAtOnce() && pictured_;
}

DrawList Workstation::traverse(const TraversalFilters& filters) {
    std::vector<int> roots;
    for (const PostedStructure& p : postedStructures()) roots.push_back(p.structureId);
    return traverser_.traverse(store_, roots, picksShownTables() ? pictureTables_ : tables_, filters);
}

void Workstation::setColourRepresentation(int index, const glm::dvec3& components) {
    tables_.colours.set(index, components, log_, static_cast<ColourModel>(colourModel_));
    changed();
}

namespace {

/// Error -208 naming `what` unless every value is finite (a NaN passes every ordered comparison
/// the standard's checks make, and an infinity reaches the transforms).
void checkFinite(std::initializer_list<double> values, ErrorLog* log, const char* function,
                 const char* what) {
    for (double v : values)
        if (!std::isfinite(v))
            raise(log, errors::NonFiniteValue, function, std::string(what) + " is not finite");
}

/// Error 136 for a direct colour with a component that is NaN or infinite (a range it may leave:
/// light and depth cue colours are clamped when drawn).
void checkFiniteColour(const Colour& colour, ErrorLog* log, const char* function) {
    if (colour.direct)
        for (int i = 0; i < 3; ++i)
            if (!std::isfinite(colour.rgb[i]))
                raise(log, errors::BadDirectColour, function, "direct colour component " + std::to_string(i));
}

void checkLineType(LineType t, ErrorLog* log, const char* function, int error = errors::BadLineType) {
    if (static_cast<int>(t) < 1 || static_cast<int>(t) > 4)
        raise(log, error, function, "type " + std::to_string(static_cast<int>(t)));
}

}  // namespace

/// The checks every SET ... REPRESENTATION of a bundle makes first, in the standard's order:
/// 100 (index < 1), 103 (a new entry beyond the table), 113 and 136 (each general colour).
template <class Table>
void Workstation::checkBundle(const Table& table, int index, std::initializer_list<Colour> colours,
                              const char* function) const {
    const std::string where = "index " + std::to_string(index);
    if (index < 1) raise(log_, errors::BundleIndexBelowOne, function, where);
    if (!table.defined(index) &&
        static_cast<int>(table.definedIndices().size()) >= description_.bundleTableSize)
        raise(log_, errors::BundleTableFull, function, where);
    for (const Colour& colour : colours) ColourTable::check(colour, log_, function);
}

void Workstation::checkAvailable(const std::vector<int>& available, int method, int error,
                                 const char* function) const {
    if (std::find(available.begin(), available.end(), method) == available.end())
        raise(log_, error, function, "method " + std::to_string(method));
}

void Workstation::setPolylineRepresentation(int index, const PolylineBundle& bundle) {
    const char* function = "SET POLYLINE REPRESENTATION";
    checkBundle(tables_.polylines, index, {bundle.colour}, function);
    checkLineType(bundle.type, log_, function);
    checkFinite({bundle.width, bundle.approximation.valueU, bundle.approximation.valueV}, log_, function,
                "the width or approximation value");
    checkAvailable(description_.polylineShadingMethods, static_cast<int>(bundle.shading),
                   errors::PolylineShadingNotAvailable, function);
    tables_.polylines.set(index, bundle, log_, function);
    changed();
}

void Workstation::setPolymarkerRepresentation(int index, const PolymarkerBundle& bundle) {
    const char* function = "SET POLYMARKER REPRESENTATION";
    checkBundle(tables_.polymarkers, index, {bundle.colour}, function);
    if (static_cast<int>(bundle.type) < 1 ||
        static_cast<int>(bundle.type) > description_.primitives.markerTypes)
        raise(log_, errors::BadMarkerType, function, "type " + std::to_string(static_cast<int>(bundle.type)));
    checkFinite({bundle.scale}, log_, function, "the marker size scale factor");
    tables_.polymarkers.set(index, bundle, log_, function);
    changed();
}

void Workstation::setTextRepresentation(int index, const TextBundle& bundle) {
    const char* function = "SET TEXT REPRESENTATION";
    checkBundle(tables_.texts, index, {bundle.colour}, function);
    if (bundle.font < 1 || bundle.font > description_.textFonts || bundle.precision < 0 ||
        bundle.precision > 2)
        raise(log_, errors::TextFontNotAvailable, function,
              "font " + std::to_string(bundle.font) + " precision " + std::to_string(bundle.precision));
    checkFinite({bundle.expansion, bundle.spacing}, log_, function, "the expansion factor or spacing");
    tables_.texts.set(index, bundle, log_, function);
    changed();
}

void Workstation::setInteriorRepresentation(int index, const InteriorBundle& bundle) {
    const char* function = "SET INTERIOR REPRESENTATION";
    checkBundle(tables_.interiors, index,
                {bundle.colour, bundle.backColour, bundle.properties.specularColour,
                 bundle.backProperties.specularColour},
                function);
    for (InteriorStyle style : {bundle.style, bundle.backStyle})
        if (static_cast<int>(style) < 0 || static_cast<int>(style) >= description_.interiorStyles)
            raise(log_, errors::BadInteriorStyle, function,
                  "style " + std::to_string(static_cast<int>(style)));
    if ((bundle.style == InteriorStyle::Pattern && bundle.styleIndex < 1) ||
        (bundle.backStyle == InteriorStyle::Pattern && bundle.backStyleIndex < 1))
        raise(log_, errors::PatternIndexBelowOne, function);
    for (ShadingMethod shading : {bundle.shading, bundle.backShading})
        checkAvailable(description_.interiorShadingMethods, static_cast<int>(shading),
                       errors::InteriorShadingNotAvailable, function);
    for (ReflectanceModel reflectance : {bundle.reflectance, bundle.backReflectance})
        checkAvailable(description_.reflectanceEquations, static_cast<int>(reflectance),
                       errors::ReflectanceNotAvailable, function);
    for (const AreaPropertiesAttribute& p : {bundle.properties, bundle.backProperties})
        checkFinite({p.ambient, p.diffuse, p.specular, p.specularExponent, p.transparency}, log_, function,
                    "an area property");
    checkFinite({bundle.approximation.valueU, bundle.approximation.valueV}, log_, function,
                "the approximation value");
    tables_.interiors.set(index, bundle, log_, function);
    changed();
}

void Workstation::setEdgeRepresentation(int index, const EdgeBundle& bundle) {
    const char* function = "SET EDGE REPRESENTATION";
    checkBundle(tables_.edges, index, {bundle.colour}, function);
    checkLineType(bundle.type, log_, function, errors::EdgeTypeNotAvailable);
    checkFinite({bundle.width}, log_, function, "the edge width scale factor");
    tables_.edges.set(index, bundle, log_, function);
    changed();
}

void Workstation::setPatternRepresentation(int index, const PatternRepresentation& pattern) {
    patterns_.set(index, pattern, log_);
    changed();
}

void Workstation::setColourModel(int model) {
    const auto& models = description_.colourModels;
    if (std::find(models.begin(), models.end(), model) == models.end())
        raise(log_, errors::ColourModelNotAvailable, "SET COLOUR MODEL", "model " + std::to_string(model));
    colourModel_ = model;  // entries keep the model they were given in: nothing to redraw
}

void Workstation::setViewRepresentation(int index, const ViewRepresentation& view) {
    tables_.views.set(index, view, log_);
    changed();
}

void Workstation::setViewTransformationInputPriority(int index, int reference, bool higher) {
    tables_.views.setInputPriority(index, reference, higher, log_);
}

void Workstation::setLightSourceRepresentation(int index, const Light& light) {
    setLightSourceRepresentation(index, light, Colour::fromRgb(glm::dvec3(light.colour)));
}

void Workstation::setLightSourceRepresentation(int index, const Light& light, const Colour& colour) {
    const char* function = "SET LIGHT SOURCE REPRESENTATION";
    if (index < 1) raise(log_, errors::BundleIndexBelowOne, function, "index " + std::to_string(index));
    if (!tables_.lights.contains(index) &&
        static_cast<int>(tables_.lights.size()) >= description_.lightTableSize)
        raise(log_, errors::BundleTableFull, function, "index " + std::to_string(index));
    checkFiniteColour(colour, log_, function);
    checkFinite(
        {light.position.x, light.position.y, light.position.z, light.direction.x, light.direction.y,
         light.direction.z, light.attenuation.x, light.attenuation.y, light.concentration, light.spreadAngle},
        log_, function, "a light source position, direction, coefficient or angle");
    Light kept = light;
    kept.colour = generalColourRgb(colour, function);
    tables_.lights[index] = kept;
    tables_.lightColours[index] = colour;
    changed();
}

void Workstation::setDepthCueRepresentation(int index, const DepthCue& cue) {
    setDepthCueRepresentation(index, cue, Colour::fromRgb(glm::dvec3(cue.colour)));
}

void Workstation::setDepthCueRepresentation(int index, const DepthCue& cue, const Colour& colour) {
    const char* function = "SET DEPTH CUE REPRESENTATION";
    if (index < 1) raise(log_, errors::BundleIndexBelowOne, function, "index " + std::to_string(index));
    if (!tables_.depthCues.contains(index) &&
        static_cast<int>(tables_.depthCues.size()) >= description_.depthCueTableSize)
        raise(log_, errors::BundleTableFull, function, "index " + std::to_string(index));
    checkFiniteColour(colour, log_, function);
    checkFinite({cue.frontPlane, cue.backPlane, cue.frontScale, cue.backScale}, log_, function,
                "a depth cue reference plane or scale factor");
    DepthCue kept = cue;
    kept.colour = generalColourRgb(colour, function);
    tables_.depthCues[index] = kept;
    tables_.depthCueColours[index] = colour;
    changed();
}

glm::vec3 Workstation::generalColourRgb(const Colour& colour, const char* function) const {
    if (!colour.direct) {
        if (colour.index < 0)
            raise(log_, errors::ColourIndexBelowZero, function,
                  "colour index " + std::to_string(colour.index));
        return glm::vec3(tables_.colours.get(colour.index));
    }
    if (!isColourModel(static_cast<int>(colour.model)))
        raise(log_, errors::ColourModelNotAvailable, function,
              "colour model " + std::to_string(static_cast<int>(colour.model)));
    return glm::vec3(toRgb(colour.model, colour.rgb));
}

void Workstation::setColourMappingRepresentation(int index, const ColourMapping& mapping) {
    tables_.colourMappings.set(index, mapping, log_, "SET COLOUR MAPPING REPRESENTATION");
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
    // Written so that a NaN fails them too.
    if (!(min.x < max.x) || !(min.y < max.y) || !(min.z <= max.z))
        raise(log_, errors::InvalidWindow, function);
    for (int i = 0; i < 3; ++i)
        if (!(min[i] >= 0.0) || !(max[i] <= 1.0)) raise(log_, errors::WorkstationWindowOutsideNpc, function);
    tables_.windowMin = min;
    tables_.windowMax = max;
    changed();
}

void Workstation::setWorkstationViewport(const glm::dvec3& min, const glm::dvec3& max) {
    const char* function = "SET WORKSTATION VIEWPORT 3";
    // Written so that a NaN fails them too.
    if (!(min.x < max.x) || !(min.y < max.y) || !(min.z <= max.z))
        raise(log_, errors::InvalidViewport, function);
    glm::dvec3 limit{description_.displaySize.x, description_.displaySize.y, 1.0};
    for (int i = 0; i < 3; ++i)
        if (!(min[i] >= 0.0) || !(max[i] <= limit[i]))
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
        if (std::find(echo_.begin(), echo_.end(), item.source.path()) != echo_.end())
            item.context.edit().highlighted = true;
    return echoed_;
}

bool Workstation::present() {
    if (!output_) return false;
    followDrawable();
    shownEcho_ = echoState();
    output_->showEcho(shownEcho_);
    // Marked first: a picture that fails to show is not tried again until it changes.
    presentedStamp_ = contentStamp();
    presented_ = true;
    return output_->present(shownPicture());
}

bool Workstation::presentationBehind() const {
    return output_ && showsChangesAtOnce() && (!presented_ || contentStamp() != presentedStamp_);
}

void Workstation::echoMoved() {
    if (!output_) return;
    // The items the last pick echoes, named by path while the list they index is the one the
    // pick was measured on.
    if (output_->drawsDeviceEchoes()) pickEchoPaths_ = lastPickEcho();
    if (echoState() != shownEcho_) present();
}

const DrawList& Workstation::pickList(const InputDevice& device) {
    TraversalFilters filters = filters_;
    filters.pick = NameSetFilter{device.pickInclusion, device.pickExclusion};
    PickList& cached = pickLists_[device.number];
    lastPickList_ = &cached.list;
    const std::uint64_t stamp = contentStamp();
    // The tables of the picture shown change only when it is regenerated (a deferred change
    // shown by UPDATE, or the switch to ASAP), without changing the stamp.
    const std::uint64_t picture = picksShownTables() ? regenerations_ + 1 : 0;
    // Nothing the traversal reads changed: the list, its generation and the Picker's tree stay.
    if (cached.made && cached.stamp == stamp && cached.picture == picture && cached.filters == filters)
        return cached.list;
    cached.list = traverse(filters);
    // A new generation per traversal lets the Picker drop intersectors of deleted surfaces.
    ++pickTraversals_;
    cached.list.generation = newGeneration();
    cached.filters = std::move(filters);
    cached.stamp = stamp;
    cached.picture = picture;
    cached.made = true;
    return cached.list;
}

std::vector<std::vector<DrawPathLevel>> Workstation::lastPickEcho() const {
    std::vector<std::vector<DrawPathLevel>> paths;
    if (!lastPickList_) return paths;
    for (std::size_t i : measurer_.lastEcho()) paths.push_back(lastPickList_->items.at(i).source.path());
    return paths;
}

EchoState Workstation::echoState() const {
    EchoState state;
    stringEcho(state);
    if (output_ && output_->drawsDeviceEchoes()) deviceEchoes(state);
    return state;
}

void Workstation::stringEcho(EchoState& state) const {
    const StringEcho typed = input_->stringEcho();
    if (typed.text.empty() && !typed.cancelled) return;
    // A window types into string device 1 (WindowEventMapper), the one that can echo it.
    if (input_->counts().string < 1) return;
    const InputDevice& d = input_->device(InputClass::String, 1);
    const EchoVolume& a = d.setup.echoVolume;
    if (d.echo != EchoSwitch::Echo || d.setup.promptEchoType != 1 || !input_->takesInput(d)) return;
    if (!(a.ymax - a.ymin >= minimumEchoLine && a.xmax - a.xmin >= a.ymax - a.ymin)) return;
    state.strings.push_back({1, a, typed.text, typed.cancelled});
}

void Workstation::deviceEchoes(EchoState& state) const {
    // The panels and sliders of the devices taking input now; those with echo on are shown.
    auto echoing = [&](InputClass inputClass, int number) -> const InputDevice* {
        const InputDevice& d = input_->device(inputClass, number);
        return d.echo == EchoSwitch::Echo ? &d : nullptr;
    };
    const EchoLayout layout = input_->activeEchoLayout();
    for (const ChoicePanel& panel : layout.panels)
        if (const InputDevice* d = echoing(InputClass::Choice, panel.device)) {
            const auto* measure = std::get_if<ChoiceMeasure>(&d->current);
            const bool chosen = measure && measure->status == InputStatus::Ok;
            state.choices.push_back({panel, chosen ? measure->choice : 0});
        }
    for (const ValuatorSlider& slider : layout.sliders)
        if (const InputDevice* d = echoing(InputClass::Valuator, slider.device)) {
            const auto* measure = std::get_if<ValuatorMeasure>(&d->current);
            state.valuators.push_back({slider, measure ? measure->value : slider.low});
        }
    // The pick echo shows what the last pick found while a device in SAMPLE or EVENT mode with
    // echo on holds it (a request ends with the pick; nothing is left to echo).
    for (int n = 1; n <= input_->counts().pick; ++n) {
        const InputDevice& d = input_->device(InputClass::Pick, n);
        if (d.mode == OperatingMode::Request || d.echo != EchoSwitch::Echo) continue;
        const auto* measure = std::get_if<PickMeasure>(&d.current);
        if (measure && measure->status == InputStatus::Ok) {
            state.picked = pickEchoPaths_;
            break;
        }
    }
}

void Workstation::followDrawable() {
    if (!output_ || !output_->followsDrawable()) return;
    const DrawableSize size = output_->drawableSize();
    if (size.width > 0 && size.height > 0) setDisplaySize({double(size.width), double(size.height)});
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
