#include "phigs/traverse/Traverser.h"

#include "FacetMesh.h"
#include "LevelCurves.h"
#include "SegmentPool.h"
#include "Tessellation.h"
#include "phigs/store/Gdp.h"
#include "phigs/store/IdTable.h"
#include "phigs/traverse/StylePool.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <climits>
#include <cmath>
#include <map>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace phigs {

namespace detail {

/// The PHIGS traversal state list (one copy per open EXECUTE STRUCTURE level).
struct State {
    int polylineIndex = 1, polymarkerIndex = 1, textIndex = 1, interiorIndex = 1, edgeIndex = 1;
    std::array<bool, static_cast<std::size_t>(AspectId::Count_)> individual{};
    LineType lineType = LineType::Solid;
    double lineWidth = 1.0;
    Colour lineColour = Colour::indexed(1);
    MarkerType markerType = MarkerType::Asterisk;
    double markerScale = 1.0;
    Colour markerColour = Colour::indexed(1);
    int font = 1, precision = 2;
    double expansion = 1.0, spacing = 0.0;
    Colour textColour = Colour::indexed(1);
    double charHeight = 0.01;
    glm::dvec2 up{0, 1};
    TextPath path = TextPath::Right;
    int hAlign = 0, vAlign = 0;
    double annoHeight = 0.01;
    glm::dvec2 annoUp{0, 1};
    TextPath annoPath = TextPath::Right;
    int annoH = 0, annoV = 0;
    int annoStyle = 1;  ///< 1 UNCONNECTED, 2 LEAD LINE
    InteriorStyle style = InteriorStyle::Hollow, backStyle = InteriorStyle::Hollow;
    int styleIndex = 1, backStyleIndex = 1;
    PatternPlacement pattern;
    Colour interiorColour = Colour::indexed(1), backColour = Colour::indexed(1);
    ShadingMethod shading = ShadingMethod::None, backShading = ShadingMethod::None;
    ShadingMethod lineShading = ShadingMethod::None;
    ReflectanceModel reflectance = ReflectanceModel::None, backReflectance = ReflectanceModel::None;
    AreaPropertiesAttribute properties{ElementType::AreaProperties};
    AreaPropertiesAttribute backProperties{ElementType::BackAreaProperties};
    int faceDistinguishing = 0, faceCulling = 0;
    bool edgeFlag = false;
    LineType edgeType = LineType::Solid;
    double edgeWidth = 1.0;
    Colour edgeColour = Colour::indexed(1);
    ApproximationAttribute curveApproximation{ElementType::CurveApproximationCriteria};
    ApproximationAttribute surfaceApproximation{ElementType::SurfaceApproximationCriteria};
    SurfaceCharacteristicsAttribute surfaceCharacteristics;
    std::set<int> lights;
    int depthCueIndex = 0;
    int colourMapIndex = 0;        ///< the colour mapping table entry colours are drawn through
    int renderingColourModel = 0;  ///< PRCM_WS_DEP (0, drawn as RGB) .. PRCM_HLS (4)
    int viewIndex = 0, pickId = 0, hlhsrId = 0;
    std::set<int> names;
    glm::dmat4 local{1.0}, global{1.0};
    glm::dmat4 composite{1.0};  ///< global * local, kept current so each item need not multiply
    bool modelClip = false;
    std::vector<glm::dvec4> clipVolume, inheritedClipVolume;  ///< world coordinates

    State() { individual.fill(true); }
    bool ind(AspectId a) const { return individual[static_cast<std::size_t>(a)]; }
    bool operator==(const State&) const = default;
};

}  // namespace detail

namespace detail {

/// A list that keeps its first value in place and the others in a vector: most lists here hold
/// one value, and reading it then touches no second block of memory.
template <class T>
class OneInline {
public:
    bool empty() const { return !hasFirst_; }
    std::size_t size() const { return hasFirst_ ? 1 + rest_.size() : 0; }
    const T* first() const { return hasFirst_ ? &first_ : nullptr; }
    void push_back(T value) {
        if (hasFirst_) {
            rest_.push_back(std::move(value));
        } else {
            first_ = std::move(value);
            hasFirst_ = true;
        }
    }
    template <class F>
    void forEach(F f) {
        if (!hasFirst_) return;
        f(first_);
        for (T& v : rest_) f(v);
    }
    template <class P>
    T* findIf(P p) {
        if (!hasFirst_) return nullptr;
        if (p(first_)) return &first_;
        for (T& v : rest_)
            if (p(v)) return &v;
        return nullptr;
    }
    /// Keeps the values `keep` accepts, in order.
    template <class P>
    void keepIf(P keep) {
        std::vector<T> kept;
        forEach([&](T& v) {
            if (keep(v)) kept.push_back(std::move(v));
        });
        *this = {};
        for (T& v : kept) push_back(std::move(v));
    }
    void popFront() {
        bool dropped = false;
        keepIf([&](const T&) { return std::exchange(dropped, true); });
    }

private:
    T first_{};
    bool hasFirst_ = false;
    std::vector<T> rest_;
};

/// A path prefix, in place when short (most networks are shallow).
struct PathPrefix {
    static constexpr std::size_t kInline = 3;
    std::array<DrawPathLevel, kInline> near{};
    std::size_t depth = 0;
    std::vector<DrawPathLevel> far;  ///< the whole prefix when deeper than kInline

    PathPrefix() = default;
    explicit PathPrefix(const std::vector<DrawPathLevel>& path) : depth(path.size()) {
        if (depth <= kInline)
            std::copy(path.begin(), path.end(), near.begin());
        else
            far = path;
    }
    bool operator==(const std::vector<DrawPathLevel>& path) const {
        if (path.size() != depth) return false;
        return depth <= kInline ? std::equal(path.begin(), path.end(), near.begin()) : far == path;
    }
};

}  // namespace detail

/// What one execution of a structure (with its descendants) produced, for a given inherited
/// state and path: reused as long as no structure of that subtree changed. The fields a reuse
/// reads lie together in place, so checking an unchanged subtree costs about one cache miss.
struct Traverser::SubtreeCache {
    struct Entry {
        std::uint64_t stamp = 0;
        std::shared_ptr<const detail::State> entry;  ///< shared by the entries made from one state
        detail::PathPrefix prefix;
        std::uint64_t elements = 0;
        std::uint64_t usedIn = 0;                           ///< the traversal that last made or reused it
        detail::OneInline<DrawItems::SegmentPtr> segments;  ///< shared with the draw lists holding them
    };
    IdTable<detail::OneInline<Entry>> entries;
    std::shared_ptr<const detail::State> lastInherited;  ///< the last state handed to an execute
    std::uint64_t traversal = 1;                         ///< the traversal under way (counted from 1)
    std::uint64_t lastSweep = 0;                         ///< the traversal of the last sweep
    std::size_t made = 0;                                ///< entries made since the last sweep
    std::size_t kept = 0;                                ///< entries the last sweep kept
    std::size_t lastSegments = 0;                        ///< the segments of the last picture

    /// Records that this traversal made or reused `e`.
    void use(Entry& e) { e.usedIn = traversal; }
    /// Drops the entries no traversal used since the last sweep. A sweep visits every entry, so
    /// it runs only once enough entries were made or traversals passed for its cost to be
    /// shared among them; until then an unused entry only holds its segments a little longer.
    /// A picture that shrank to under half the segments of the last sweeps at once, keeping the
    /// entries this traversal used and those whose segments it still draws (nested in an entry it
    /// reused, which it did not visit): the old picture's segments are let go of now.
    void prune(const DrawItems& picture) {
        const std::size_t segments = picture.segmentCount();
        const bool shrank = segments * 2 < lastSegments;
        lastSegments = segments;
        if (traversal - lastSweep < kSweepEvery && made * 8 <= kept + 64 && !shrank) {
            endTraversal();
            return;
        }
        std::unordered_set<const DrawSegment*> drawn;
        if (shrank)
            for (const DrawItems::SegmentPtr& segment : picture.segments()) drawn.insert(segment.get());
        auto keep = [&](const Entry& e) {
            if (!shrank) return e.usedIn > lastSweep;
            const DrawItems::SegmentPtr* first = e.segments.first();
            return e.usedIn == traversal || (first && drawn.contains(first->get()));
        };
        kept = 0;
        entries.forEach([&](int, detail::OneInline<Entry>& list) {
            list.keepIf(keep);
            kept += list.size();
        });
        made = 0;
        lastSweep = traversal;
        endTraversal();
    }
    void endTraversal() { ++traversal; }
    void clear() {
        entries.clear();
        made = kept = lastSegments = 0;
        lastSweep = traversal - 1;
    }
    static constexpr std::size_t kSweepEvery = 16;
};

/// What a structure's elements before its first execute make (items, and items that copy their
/// points), by structure version: the segment for them is sized without reading every element's
/// family once more before the walk reads it (a hint: a stale entry only sizes a segment wrong).
struct Traverser::RunSizes {
    struct Sizes {
        std::uint64_t version = 0;  ///< 0: none (a structure's version is never 0 once edited)
        std::uint32_t primitives = 0, copying = 0;
        bool operator==(const Sizes&) const = default;
    };
    IdTable<Sizes> byId;
};

/// Light sets and depth cues as draw items index them, kept across traversals so that an item
/// reused from an earlier traversal keeps valid indices: an index is only ever added, and a
/// lookup compares the resolved values, so a changed table gets new entries.
struct Traverser::ItemTables {
    std::map<std::set<int>, std::vector<int>> lightIndices;
    std::vector<std::vector<Light>> lightSets;
    std::map<int, std::vector<int>> cueIndices;
    std::vector<DepthCue> depthCues;
    /// The interned styles of the items (shared with the segments that view them).
    std::shared_ptr<StylePool> styles = std::make_shared<StylePool>();

    /// Past this many entries the tables start again (and so must every cached subtree).
    static constexpr std::size_t kLimit = 4096;
    bool full() const { return lightSets.size() + depthCues.size() > kLimit || styles->size() > 16 * kLimit; }

    int lightSet(const std::set<int>& active, std::vector<Light> lights) {
        auto& candidates = lightIndices[active];
        for (int i : candidates)
            if (lightSets[static_cast<std::size_t>(i)] == lights) return i;
        candidates.push_back(static_cast<int>(lightSets.size()));
        lightSets.push_back(std::move(lights));
        return candidates.back();
    }
    int depthCue(int index, const DepthCue& cue) {
        auto& candidates = cueIndices[index];
        for (int i : candidates)
            if (depthCues[static_cast<std::size_t>(i)] == cue) return i;
        candidates.push_back(static_cast<int>(depthCues.size()));
        depthCues.push_back(cue);
        return candidates.back();
    }
};

namespace {

using detail::State;

/// Free draw segments kept past what the last traversal took.
constexpr std::size_t kSpareSegments = 64;

glm::dmat4 compose(const glm::dmat4& current, const TransformElement& t) {
    switch (t.composition) {
        case Composition::Preconcatenate:
            return current * t.matrix;
        case Composition::Postconcatenate:
            return t.matrix * current;
        case Composition::Replace:
            break;
    }
    return t.matrix;
}

void applyIndex(State& s, const IndexAttribute& a) {
    using T = ElementType;
    const int v = a.value;
    switch (a.type) {
        case T::PolylineIndex:
            s.polylineIndex = v;
            break;
        case T::PolymarkerIndex:
            s.polymarkerIndex = v;
            break;
        case T::TextIndex:
            s.textIndex = v;
            break;
        case T::InteriorIndex:
            s.interiorIndex = v;
            break;
        case T::EdgeIndex:
            s.edgeIndex = v;
            break;
        case T::Linetype:
            s.lineType = static_cast<LineType>(v);
            break;
        case T::MarkerType:
            s.markerType = static_cast<MarkerType>(v);
            break;
        case T::TextFont:
            s.font = v;
            break;
        case T::TextPrecision:
            s.precision = v;
            break;
        case T::TextPath:
            s.path = static_cast<TextPath>(v);
            break;
        case T::AnnotationTextPath:
            s.annoPath = static_cast<TextPath>(v);
            break;
        case T::AnnotationStyle:
            s.annoStyle = v;
            break;
        case T::InteriorStyle:
            s.style = static_cast<InteriorStyle>(v);
            break;
        case T::InteriorStyleIndex:
            s.styleIndex = v;
            break;
        case T::BackInteriorStyle:
            s.backStyle = static_cast<InteriorStyle>(v);
            break;
        case T::BackInteriorStyleIndex:
            s.backStyleIndex = v;
            break;
        case T::InteriorShadingMethod:
            s.shading = static_cast<ShadingMethod>(v);
            break;
        case T::BackInteriorShadingMethod:
            s.backShading = static_cast<ShadingMethod>(v);
            break;
        case T::InteriorReflectanceEquation:
            s.reflectance = static_cast<ReflectanceModel>(v);
            break;
        case T::BackInteriorReflectanceEquation:
            s.backReflectance = static_cast<ReflectanceModel>(v);
            break;
        case T::FaceDistinguishingMode:
            s.faceDistinguishing = v;
            break;
        case T::FaceCullingMode:
            s.faceCulling = v;
            break;
        case T::EdgeFlag:
            s.edgeFlag = v != 0;
            break;
        case T::Edgetype:
            s.edgeType = static_cast<LineType>(v);
            break;
        case T::DepthCueIndex:
            s.depthCueIndex = v;
            break;
        case T::ColourMappingIndex:
            s.colourMapIndex = v;
            break;
        case T::RenderingColourModel:
            s.renderingColourModel = v;
            break;
        case T::ViewIndex:
            s.viewIndex = v;
            break;
        case T::PickId:
            s.pickId = v;
            break;
        case T::HlhsrIdentifier:
            s.hlhsrId = v;
            break;
        case T::ModelClippingIndicator:
            s.modelClip = v != 0;
            break;
        case T::PolylineShadingMethod:
            s.lineShading = static_cast<ShadingMethod>(v);
            break;
        default:
            break;
    }
}

void applyReal(State& s, const RealAttribute& a) {
    using T = ElementType;
    switch (a.type) {
        case T::LinewidthScaleFactor:
            s.lineWidth = a.value;
            break;
        case T::MarkerSizeScaleFactor:
            s.markerScale = a.value;
            break;
        case T::CharacterExpansionFactor:
            s.expansion = a.value;
            break;
        case T::CharacterSpacing:
            s.spacing = a.value;
            break;
        case T::CharacterHeight:
            s.charHeight = a.value;
            break;
        case T::AnnotationTextCharacterHeight:
            s.annoHeight = a.value;
            break;
        case T::EdgewidthScaleFactor:
            s.edgeWidth = a.value;
            break;
        default:
            break;
    }
}

void applyColour(State& s, const ColourAttribute& a) {
    using T = ElementType;
    switch (a.type) {
        case T::PolylineColour:
            s.lineColour = a.colour;
            break;
        case T::PolymarkerColour:
            s.markerColour = a.colour;
            break;
        case T::TextColour:
            s.textColour = a.colour;
            break;
        case T::InteriorColour:
            s.interiorColour = a.colour;
            break;
        case T::BackInteriorColour:
            s.backColour = a.colour;
            break;
        case T::EdgeColour:
            s.edgeColour = a.colour;
            break;
        default:
            break;
    }
}

/// Resolves the state against the workstation tables.
struct Resolver {
    const WorkstationTables& t;
    /// A colour as drawn: through the colour table, then colour mapping entry `mapping`.
    glm::vec3 rgb(const Colour& c, int mapping) const {
        const glm::dvec3 v = t.colours.resolve(c);
        return glm::vec3(t.colourMappings.identity(mapping) ? v
                                                            : t.colourMappings.map(mapping, v, t.colours));
    }
    glm::vec3 rgb(const Colour& c, const State& s) const { return rgb(c, s.colourMapIndex); }
    /// Whether colour mapping entry `mapping` changes colours.
    bool maps(int mapping) const { return !t.colourMappings.identity(mapping); }

    LineStyle line(const State& s) const {
        const PolylineBundle& b = t.polylines.get(s.polylineIndex);
        return {rgb(s.ind(AspectId::PolylineColour) ? s.lineColour : b.colour, s),
                t.limits.lineType(s.ind(AspectId::LineType) ? s.lineType : b.type),
                static_cast<float>(
                    t.limits.lineWidthScale(s.ind(AspectId::LinewidthScale) ? s.lineWidth : b.width))};
    }
    /// Whether polylines with vertex colours interpolate them (polyline shading method COLOUR).
    bool lineShaded(const State& s) const {
        const ShadingMethod m =
            s.ind(AspectId::PolylineShading) ? s.lineShading : t.polylines.get(s.polylineIndex).shading;
        return m == ShadingMethod::Colour;
    }
    MarkerStyle marker(const State& s) const {
        const PolymarkerBundle& b = t.polymarkers.get(s.polymarkerIndex);
        return {rgb(s.ind(AspectId::PolymarkerColour) ? s.markerColour : b.colour, s),
                t.limits.markerType(s.ind(AspectId::MarkerType) ? s.markerType : b.type),
                static_cast<float>(
                    t.limits.markerScale(s.ind(AspectId::MarkerSizeScale) ? s.markerScale : b.scale))};
    }
    TextStyle text(const State& s, bool annotation) const {
        const TextBundle& b = t.texts.get(s.textIndex);
        TextStyle out;
        out.colour = rgb(s.ind(AspectId::TextColour) ? s.textColour : b.colour, s);
        out.font = s.ind(AspectId::TextFont) ? s.font : b.font;
        // ISO 9592 draws a height or expansion factor by its absolute value.
        out.expansion =
            static_cast<float>(std::abs(s.ind(AspectId::CharacterExpansion) ? s.expansion : b.expansion));
        out.spacing = static_cast<float>(s.ind(AspectId::CharacterSpacing) ? s.spacing : b.spacing);
        out.height = std::abs(annotation ? s.annoHeight : s.charHeight);
        out.upVector = annotation ? s.annoUp : s.up;
        out.path = annotation ? s.annoPath : s.path;
        out.horizontal = static_cast<HorizontalAlignment>(annotation ? s.annoH : s.hAlign);
        out.vertical = static_cast<VerticalAlignment>(annotation ? s.annoV : s.vAlign);
        return out;
    }
    Reflectance reflectance(const AreaPropertiesAttribute& a) const {
        return {static_cast<float>(a.ambient),
                static_cast<float>(a.diffuse),
                static_cast<float>(a.specular),
                glm::vec3(t.colours.resolve(a.specularColour)),  // a reflectance property: not mapped
                static_cast<float>(a.specularExponent),
                static_cast<float>(a.transparency)};
    }
    InteriorStyleSet interior(const State& s) const {
        const InteriorBundle& b = t.interiors.get(s.interiorIndex);
        InteriorStyleSet out;
        out.style = s.ind(AspectId::InteriorStyle) ? s.style : b.style;
        out.styleIndex =
            t.limits.styleIndex(out.style, s.ind(AspectId::InteriorStyleIndex) ? s.styleIndex : b.styleIndex);
        out.pattern = s.pattern;
        out.colour = rgb(s.ind(AspectId::InteriorColour) ? s.interiorColour : b.colour, s);
        out.backColour = rgb(s.ind(AspectId::BackInteriorColour) ? s.backColour : b.backColour, s);
        out.shading = s.ind(AspectId::InteriorShading) ? s.shading : b.shading;
        out.reflectance = s.ind(AspectId::InteriorReflectance) ? s.reflectance : b.reflectance;
        out.properties = reflectance(s.ind(AspectId::AreaProperties) ? s.properties : b.properties);
        out.backProperties =
            reflectance(s.ind(AspectId::BackAreaProperties) ? s.backProperties : b.backProperties);
        out.cull = static_cast<CullMode>(s.faceCulling);
        out.distinguishBackFaces = s.faceDistinguishing != 0;
        // Workstation dependent (0) and models no workstation has are drawn in RGB, as the
        // standard asks for a model that is not available.
        out.renderingModel = isColourModel(s.renderingColourModel)
                                 ? static_cast<ColourModel>(s.renderingColourModel)
                                 : ColourModel::Rgb;
        const InteriorStyle backStyle = s.ind(AspectId::BackInteriorStyle) ? s.backStyle : b.backStyle;
        out.back = {
            backStyle,
            t.limits.styleIndex(
                backStyle, s.ind(AspectId::BackInteriorStyleIndex) ? s.backStyleIndex : b.backStyleIndex),
            s.ind(AspectId::BackInteriorShading) ? s.backShading : b.backShading,
            s.ind(AspectId::BackInteriorReflectance) ? s.backReflectance : b.backReflectance};
        return out;
    }
    EdgeStyle edge(const State& s) const {
        const EdgeBundle& b = t.edges.get(s.edgeIndex);
        return {s.ind(AspectId::EdgeFlag) ? s.edgeFlag : b.visible,
                rgb(s.ind(AspectId::EdgeColour) ? s.edgeColour : b.colour, s),
                t.limits.lineType(s.ind(AspectId::EdgeType) ? s.edgeType : b.type),
                static_cast<float>(
                    t.limits.lineWidthScale(s.ind(AspectId::EdgewidthScale) ? s.edgeWidth : b.width))};
    }
    ApproximationAttribute curveApproximation(const State& s) const {
        return s.ind(AspectId::CurveApproximation) ? s.curveApproximation
                                                   : t.polylines.get(s.polylineIndex).approximation;
    }
    ApproximationAttribute surfaceApproximation(const State& s) const {
        return s.ind(AspectId::SurfaceApproximation) ? s.surfaceApproximation
                                                     : t.interiors.get(s.interiorIndex).approximation;
    }
};

/// Both sides flat shaded (interior shading method NONE): a facet is one colour, its facet colour
/// or else the interior colour, and vertex colours play no part (the rule HP-PHIGS documents).
bool flatShaded(const InteriorStyleSet& interior) {
    return interior.shadingOf(false) == ShadingMethod::None &&
           interior.shadingOf(true) == ShadingMethod::None;
}

bool anyIndexed(const std::vector<Colour>& colours) {
    for (const Colour& c : colours)
        if (!c.direct) return true;
    return false;
}

/// What a line style is resolved from (the state's side; the tables stay for a traversal).
struct LineInputs {
    int bundle = 0, colourMap = 0;
    unsigned individual = 0;  ///< the ASFs of colour, type and width, one bit each
    Colour colour;
    LineType type = LineType::Solid;
    double width = 0.0;
    bool operator==(const LineInputs&) const = default;
};
/// A line style interned for its inputs.
struct LineMemo {
    LineInputs key;
    const LineStyle* record = nullptr;
};

class Walk {
public:
    Walk(const StructureStore& store, const WorkstationTables& tables, const TraversalFilters& filters,
         TessellationCache& cache, Traverser::SubtreeCache* subtrees, Traverser::ItemTables& itemTables,
         Traverser::RunSizes& runSizes, detail::SegmentPool& segmentPool, DrawList& out)
        : store_(store),
          tables_(tables),
          filters_(filters),
          cache_(cache),
          out_(out),
          resolve_{tables},
          subtrees_(subtrees),
          itemTables_(itemTables),
          runSizes_(runSizes),
          segmentPool_(segmentPool),
          baseStamp_(baseStamp(tables, filters)) {}

    std::uint64_t visited = 0;
    std::uint64_t reused = 0;
    std::size_t maxPictureBytes = kMaxPictureBytes;

    void root(int id) {
        State state;
        state.names = filters_.initialNames;
        walk(id, state);
        flush();
    }
    /// Lets go of the segment being built (a traversal that failed).
    void abandon() { segment_.reset(); }

private:
    void walk(int id, State& state) {
        const Structure* s = store_.find(id);
        if (!s) return;
        // What the executes here hand down, made once until an element may change the state.
        std::shared_ptr<const State> child;
        ++epoch_;              // another state: the styles resolved so far are not its
        bool firstRun = true;  // no execute passed yet
        for (std::size_t i = 0; i < s->elements.size(); ++i) {
            ++visited;
            const int number = static_cast<int>(i) + 1;
            if (auto x = s->elements.get<ExecuteStructureElement>(i)) {
                firstRun = false;
                if (!child) child = inherited(state);
                path_.push_back({id, number, state.pickId});
                execute(x->structureId, child);
                path_.pop_back();
                ++epoch_;
                continue;
            }
            child.reset();
            const bool primitive = mayDraw(s->elements.family(i));
            if (!primitive)
                ++epoch_;  // the state may change
            else if (!segment_)
                segment_ = newSegment(*s, i, firstRun);
            apply(*s, i, number, state);
        }
    }

    /// The state a structure executed from `state` starts with (a push: the child inherits,
    /// and nothing it sets comes back). Equal to the last one handed down, it is that one, so
    /// a cached subtree's state compares by pointer.
    std::shared_ptr<const State> inherited(const State& state) {
        auto child = std::make_shared<State>(state);
        child->global = state.composite;
        child->local = glm::dmat4(1.0);
        child->inheritedClipVolume = child->clipVolume;
        if (!subtrees_) return child;
        std::shared_ptr<const State>& last = subtrees_->lastInherited;
        if (last && *last == *child) return last;
        last = child;
        return last;
    }

    static std::uint64_t mix(std::uint64_t hash, std::uint64_t value) {
        return (hash ^ value) * 1099511628211ull;
    }

    static std::uint64_t baseStamp(const WorkstationTables& tables, const TraversalFilters& filters) {
        std::uint64_t h = mix(1469598103934665603ull, tables.generation);
        auto set = [&](const std::set<int>& names) {
            h = mix(h, names.size());
            for (int n : names) h = mix(h, static_cast<std::uint32_t>(n));
        };
        auto filter = [&](const std::optional<NameSetFilter>& f) {
            h = mix(h, f.has_value());
            if (f) set(f->inclusion), set(f->exclusion);
        };
        filter(filters.pick), filter(filters.highlight), filter(filters.invisibility),
            set(filters.initialNames);
        return h;
    }

    /// What a subtree's reuse depends on: the tables, the filters and the store's version of
    /// every structure the subtree executes (kept by the store, so no walk of the subtree).
    std::uint64_t subtreeStamp(int id) const {
        return mix(mix(baseStamp_, static_cast<std::uint32_t>(id)), store_.subtreeVersion(id));
    }

    [[noreturn]] static void tooDeep() {
        throw Error(errors::NetworkTooDeep, "TRAVERSAL",
                    "more than " + std::to_string(kMaxNetworkDepth) + " nested EXECUTE STRUCTURE levels");
    }

    /// Refuses a picture past maxPictureBytes (checked at each segment: cheap, and in time).
    void checkPictureSize() const {
        constexpr std::size_t kSegmentBytes = 1024, kItemBytes = 64;
        const std::size_t segments = out_.items.segmentCount(), items = out_.items.size();
        if (segments * kSegmentBytes + items * kItemBytes > maxPictureBytes)
            throw Error(errors::StorageOverflow, "TRAVERSAL",
                        "the picture would take more than " + std::to_string(maxPictureBytes >> 10) +
                            " KiB (" + std::to_string(segments) + " structure parts, " +
                            std::to_string(items) + " items so far)");
    }

    void execute(int id, const std::shared_ptr<const State>& child) {
        if (path_.size() > kMaxNetworkDepth) tooDeep();
        if (!subtrees_) {
            State state = *child;
            flush();  // one segment per structure part: small blocks, no giant reallocation
            walk(id, state);
            flush();
            return;
        }
        const std::uint64_t stamp = subtreeStamp(id);
        flush();
        auto sameExecution = [&](const Traverser::SubtreeCache::Entry& e) {
            return (e.entry == child || *e.entry == *child) && e.prefix == path_;
        };
        auto matches = [&](const Traverser::SubtreeCache::Entry& e) {
            return e.stamp == stamp && sameExecution(e);
        };
        if (auto* found = subtrees_->entries.find(id))
            if (auto* e = found->findIf(matches)) {
                // Unchanged: the same segments again, shared, no item copied.
                subtrees_->use(*e);
                reused += e->elements;
                e->segments.forEach(
                    [&](const DrawItems::SegmentPtr& segment) { out_.items.appendSegment(segment); });
                checkPictureSize();
                return;
            }
        const std::size_t firstSegment = out_.items.segmentCount();
        const std::uint64_t firstElements = visited + reused;
        State state = *child;
        walk(id, state);
        flush();
        Traverser::SubtreeCache::Entry e;
        e.entry = child;
        e.prefix = detail::PathPrefix(path_);
        e.stamp = stamp;
        const auto& segments = out_.items.segments();
        for (std::size_t k = firstSegment; k < segments.size(); ++k) e.segments.push_back(segments[k]);
        e.elements = visited + reused - firstElements;
        auto& list = subtrees_->entries[id];
        // The entry this execution made before a change can never match again: its segments go now.
        if (list.findIf(sameExecution))
            list.keepIf([&](const Traverser::SubtreeCache::Entry& old) { return !sameExecution(old); });
        if (list.size() >= 8) list.popFront();
        subtrees_->use(e);
        list.push_back(std::move(e));
        ++subtrees_->made;
    }

    /// A segment with room for every primitive up to the next execute (one item each: only a
    /// polyline set, a set of fill area sets or edge data makes more, and the segment grows for
    /// those).
    /// firstRun: `from` lies before the structure's first execute (its sizes are kept by version).
    std::shared_ptr<DrawSegment> newSegment(const Structure& s, std::size_t from, bool firstRun) const {
        std::size_t primitives = 0, copying = 0;
        Traverser::RunSizes::Sizes* kept = firstRun && s.version != 0 ? &runSizes_.byId[s.id] : nullptr;
        if (kept && kept->version == s.version) {
            primitives = kept->primitives, copying = kept->copying;
        } else {
            for (std::size_t i = from; i < s.elements.size(); ++i) {
                if (s.elements.get<ExecuteStructureElement>(i)) break;
                const std::size_t family = s.elements.family(i);
                primitives += mayDraw(family);
                copying += mayDraw(family) && !viewsStoredPoints(family);
            }
            if (kept)
                *kept = {s.version, static_cast<std::uint32_t>(primitives),
                         static_cast<std::uint32_t>(copying)};
        }
        auto segment = segmentPool_.take();
        segment->items.reserve(primitives);
        segment->points.reserve(copying * 4);
        segment->source.set(path_, s.id, s.version);
        segment->styles = itemTables_.styles;
        segment->storePoints = s.elements.pointPool();  // a segment's items are one structure's
        return segment;
    }
    /// A view of a stored point list, in the pool the segment holds.
    static ItemArray<glm::dvec3> storedPoints(const PointList& points) {
        return ItemArray<glm::dvec3>::view(points.data(), points.size());
    }
    /// A view of a copy of `points` in the segment being built.
    ItemArray<glm::dvec3> segmentPoints(std::span<const glm::dvec3> points) const {
        return ItemArray<glm::dvec3>::view(segment_->points.add(points.data(), points.size()), points.size());
    }
    static bool mayDraw(std::size_t family) {
        return family <= kLastPrimitive || family == detail::AlternativeIndex<GdpElement, Element>::value;
    }
    /// Polylines and polymarkers draw from the store's points (storedPoints), copying none.
    static bool viewsStoredPoints(std::size_t family) {
        return family == detail::AlternativeIndex<PolylineElement, Element>::value ||
               family == detail::AlternativeIndex<PolymarkerElement, Element>::value;
    }
    /// The variant index of the last output primitive family (they come first in Element).
    static constexpr std::size_t kLastPrimitive = 14;
    static_assert(
        std::is_same_v<std::variant_alternative_t<kLastPrimitive, Element>, SetOfFillAreaSetsElement>);

    /// Ends the segment being built: later items go to a new one.
    void flush() {
        if (segment_ && !segment_->items.empty()) {
            out_.items.appendSegment(std::move(segment_));
            checkPictureSize();
        }
        segment_.reset();
        transform_ = nullptr;
        clip_ = {};
        context_ = lastContext_ = nullptr;
        contextEpoch_ = 0;
    }

    /// The segment's record of the current transform: a new one only when it changed.
    ItemRef<glm::dmat4> transform(const State& state) {
        // The state may have changed: compare (out of line, so the common case inlines).
        if (!transform_ || transformEpoch_ != epoch_) newTransform(state);
        return ItemRef<glm::dmat4>::view(transform_);
    }
    [[gnu::noinline]] void newTransform(const State& state) {
        if (!transform_ || *transform_ != state.composite)
            transform_ = segment_->transforms.add(&state.composite, 1);
        transformEpoch_ = epoch_;
    }
    /// The segment's copy of the current model clipping volume, shared by the items it holds for.
    ItemArray<glm::dvec4> clipPlanes(const State& state) {
        const std::vector<glm::dvec4>& v = state.clipVolume;
        if (clip_.size() != v.size() || !std::equal(v.begin(), v.end(), clip_.begin()))
            clip_ = std::span<const glm::dvec4>(segment_->rareRecords().clipPlanes.add(v.data(), v.size()),
                                                v.size());
        return ItemArray<glm::dvec4>::view(clip_.data(), clip_.size());
    }

    template <class T>
    static ItemRef<T> viewOf(const T* record) {
        return ItemRef<T>::view(record);
    }
    ItemRef<LineStyle> intern(const LineStyle& v) { return viewOf(styles_.lines.intern(v)); }
    ItemRef<MarkerStyle> intern(const MarkerStyle& v) { return viewOf(styles_.markers.intern(v)); }
    ItemRef<TextStyle> intern(const TextStyle& v) { return viewOf(styles_.texts.intern(v)); }
    ItemRef<InteriorStyleSet> intern(const InteriorStyleSet& v) {
        return viewOf(styles_.interiors.intern(v));
    }
    ItemRef<EdgeStyle> intern(const EdgeStyle& v) { return viewOf(styles_.edges.intern(v)); }

    /// A style resolved from the state, interned once per state: later items of the same state
    /// reuse the record without resolving again.
    template <class T>
    struct Resolved {
        std::uint64_t epoch = 0;
        const T* record = nullptr;
    };
    template <class T, class Resolve>
    ItemRef<T> resolved(Resolved<T>& cached, Resolve resolve) {
        if (cached.epoch != epoch_) cached = {epoch_, intern(resolve()).operator->()};
        return viewOf(cached.record);
    }
    /// A line style per state, resolved and interned once per distinct inputs: a scene switches
    /// among few line styles, and most states repeat one seen before.
    ItemRef<LineStyle> line(const State& s) {
        if (line_.epoch != epoch_) newLine(s);  // out of line, so the common case inlines
        return viewOf(line_.record);
    }
    [[gnu::noinline]] void newLine(const State& s) {
        const LineInputs in{s.polylineIndex,
                            s.colourMapIndex,
                            unsigned(s.ind(AspectId::PolylineColour)) |
                                unsigned(s.ind(AspectId::LineType)) << 1 |
                                unsigned(s.ind(AspectId::LinewidthScale)) << 2,
                            s.lineColour,
                            s.lineType,
                            s.lineWidth};
        std::uint64_t h = mix(mix(mix(1469598103934665603ull, std::uint64_t(in.bundle)), in.individual),
                              std::uint64_t(in.type) * 31 + std::uint64_t(in.colourMap));
        h = mix(mix(h, std::bit_cast<std::uint64_t>(in.width)),
                in.colour.direct ? std::bit_cast<std::uint64_t>(in.colour.rgb.x + 3 * in.colour.rgb.y +
                                                                7 * in.colour.rgb.z)
                                 : std::uint64_t(in.colour.index));
        LineMemo& memo = lineMemo_[(h ^ (h >> 29)) % lineMemo_.size()];
        if (!memo.record || !(memo.key == in)) memo = {in, intern(resolve_.line(s)).operator->()};
        line_ = {epoch_, memo.record};
    }
    ItemRef<MarkerStyle> marker(const State& s) {
        return resolved(marker_, [&] { return resolve_.marker(s); });
    }
    ItemRef<InteriorStyleSet> interior(const State& s) {
        return resolved(interior_, [&] { return resolve_.interior(s); });
    }
    ItemRef<EdgeStyle> edge(const State& s) {
        return resolved(edge_, [&] { return resolve_.edge(s); });
    }

    /// What every item of one state shares besides its styles: resolved once per state.
    struct ItemFields {
        std::uint64_t epoch = 0;
        bool invisible = false, highlighted = false, pickable = true;
        std::int32_t viewIndex = 0, lightSet = -1, depthCue = -1;
    };
    const ItemFields& itemFields(const State& state) {
        if (fields_.epoch != epoch_) newItemFields(state);  // out of line, so the common case inlines
        return fields_;
    }
    [[gnu::noinline]] void newItemFields(const State& state) {
        fields_.epoch = epoch_;
        fields_.invisible = filters_.invisibility && filters_.invisibility->accepts(state.names);
        if (fields_.invisible) return;  // no item: nothing else is asked for
        fields_.highlighted = filters_.highlight && filters_.highlight->accepts(state.names);
        fields_.pickable = !filters_.pick || filters_.pick->accepts(state.names);
        fields_.viewIndex = tables_.views.defined(state.viewIndex) ? state.viewIndex : 0;
        fields_.lightSet = lightSet(state.lights);
        fields_.depthCue = depthCue(state.depthCueIndex);
    }

    /// The segment's records of an out-of-line kind of primitive.
    template <class P>
    static auto& records(DrawSegment& segment) {
        if constexpr (std::is_same_v<P, DrawMesh>)
            return segment.meshes;
        else if constexpr (std::is_same_v<P, DrawFillArea>)
            return segment.rareRecords().fillAreas;
        else if constexpr (std::is_same_v<P, DrawText>)
            return segment.rareRecords().texts;
        else if constexpr (std::is_same_v<P, DrawCurve>)
            return segment.rareRecords().curves;
        else if constexpr (std::is_same_v<P, DrawColouredPolyline>)
            return segment.rareRecords().colouredPolylines;
        else
            static_assert(kUnhandledPrimitive<P>);
    }
    /// A primitive as its item holds it: an out-of-line one in the segment, viewed; one held in
    /// place as itself, so that the item's variant is made from it directly.
    template <class Primitive>
    detail::HeldAs<std::decay_t<Primitive>> held(Primitive&& primitive) {
        using P = std::decay_t<Primitive>;
        if constexpr (detail::kHeldOutOfLine<P>)
            return ItemRef<P>::view(&records<P>(*segment_).emplace_back(std::forward<Primitive>(primitive)));
        else
            return std::forward<Primitive>(primitive);
    }

    /// The segment's context for the items of the current state (null: they are invisible),
    /// a new record only when the state changed what it holds.
    const DrawContext* context(const State& state) {
        if (contextEpoch_ != epoch_) newContext(state);  // out of line, so the common case inlines
        return context_;
    }
    [[gnu::noinline]] void newContext(const State& state) {
        contextEpoch_ = epoch_;
        const ItemFields& f = itemFields(state);
        context_ = nullptr;
        if (f.invisible) return;
        ItemRef<glm::dmat4> t = transform(state);
        ItemArray<glm::dvec4> clip = state.modelClip ? clipPlanes(state) : ItemArray<glm::dvec4>{};
        const DrawContext* last = lastContext_;
        if (last && last->modelTransform.sameRecord(t) && last->viewIndex == f.viewIndex &&
            last->lightSet == f.lightSet && last->depthCue == f.depthCue &&
            last->highlighted == f.highlighted && last->pickable == f.pickable &&
            last->modelClipPlanes.data() == clip.data() && last->modelClipPlanes.size() == clip.size()) {
            context_ = last;  // an attribute of the primitives changed, not their context
            return;
        }
        context_ = lastContext_ = &segment_->contexts.emplace_back(DrawContext{
            std::move(t), f.viewIndex, f.lightSet, f.depthCue, f.highlighted, f.pickable, std::move(clip)});
    }

    template <class Primitive>
    DrawItem* emit(const Structure& /*the segment's*/, int number, const State& state,
                   Primitive&& primitive) {
        // Whether the item owns something is asked of the primitive before it is moved in: a
        // copy made from an lvalue would own what the answer did not count.
        static_assert(!std::is_lvalue_reference_v<Primitive>, "emit takes its primitive by move");
        const DrawContext* shared = context(state);
        if (!shared) return nullptr;
        // Built in place (the storage may hold a cold item of an earlier traversal: written once).
        // Out-of-line primitives become views of the segment's records, which own nothing.
        bool owns = false;  // nor do the other fields: they view the segment too
        if constexpr (!detail::kHeldOutOfLine<std::decay_t<Primitive>>)
            owns = ItemVector::ownsSomething(primitive);
        DrawItem& item = segment_->items.emplaceKnown(
            owns, held(std::forward<Primitive>(primitive)), ItemRef<DrawContext>::view(shared),
            DrawSource::view(&segment_->source, number, state.pickId));
        return &item;
    }

    int lightSet(const std::set<int>& active) {
        // No active light is a light set too: lit interiors sum over no lights and come out black.
        auto [it, fresh] = lightSets_.try_emplace(active, 0);
        if (fresh) {
            std::vector<Light> lights;
            for (int index : active)
                if (const auto l = tables_.drawnLight(index)) lights.push_back(*l);  // drawn as realized
            it->second = itemTables_.lightSet(active, std::move(lights));
        }
        return it->second;
    }

    int depthCue(int index) {
        if (index == lastCue_.first) return lastCue_.second;
        const int used = tables_.depthCues.contains(index) ? index : 0;
        int result = -1;
        if (const auto cue = tables_.drawnDepthCue(used); cue && cue->enabled)
            result = itemTables_.depthCue(used, *cue);
        lastCue_ = {index, result};
        return result;
    }

    std::vector<glm::vec3> resolveColours(const std::vector<Colour>& colours, const State& state) const {
        std::vector<glm::vec3> out;
        out.reserve(colours.size());
        for (const Colour& c : colours) out.push_back(resolve_.rgb(c, state));
        return out;
    }

    void apply(const Structure& s, std::size_t index, int number, State& state) {
        const std::uint64_t serial = s.elements.serial(index);
        visitElement(
            [&](const auto& e) {
                using E = std::decay_t<decltype(e)>;
                if constexpr (std::is_same_v<E, PolylineElement>) {
                    if (e.points.size() >= 2)
                        emit(s, number, state, DrawPolyline{storedPoints(e.points), line(state)});
                } else if constexpr (std::is_same_v<E, PolymarkerElement>) {
                    if (!e.points.empty())
                        emit(s, number, state, DrawPolymarker{storedPoints(e.points), marker(state)});
                } else if constexpr (std::is_same_v<E, FillAreaElement>) {
                    if (e.points.size() >= 3) {
                        DrawFillArea f;
                        f.contours = {e.points.toVector()};
                        fillStyle(f, state);
                        emit(s, number, state, std::move(f));
                    }
                } else if constexpr (std::is_same_v<E, FillAreaSetElement>) {
                    DrawFillArea f;
                    for (const auto& c : e.contours)
                        if (c.size() >= 3) f.contours.push_back(c);
                    if (!f.contours.empty()) {
                        fillStyle(f, state);
                        emit(s, number, state, std::move(f));
                    }
                } else if constexpr (std::is_same_v<E, FillAreaSetWithDataElement>) {
                    DrawFillArea f;
                    f.contours = e.contours;
                    f.vertexNormals = e.vertexNormals;
                    if (e.hasFacetNormal) f.facetNormal = e.facetNormal;
                    fillStyle(f, state);
                    if (!flatShaded(*f.interior))
                        for (const auto& c : e.vertexColours)
                            f.vertexColours.push_back(resolveColours(c, state));
                    if (e.hasFacetColour) f.interior = facetColoured(*f.interior, e.facetColour, state);
                    std::vector<std::vector<glm::dvec3>> edges;
                    const bool edgeData = !e.edgeFlags.empty() && f.edges->visible;
                    if (edgeData)
                        for (std::size_t c = 0; c < e.contours.size(); ++c)
                            if (e.contours[c].size() >= 2) visibleEdges(e.contours[c], e.edgeFlags[c], edges);
                    emitWithEdges(s, number, state, std::move(f), edgeData, edges);
                } else if constexpr (std::is_same_v<E, TextElement>) {
                    DrawText t;
                    t.text = e.text;
                    t.position = e.position;
                    t.direction1 = e.direction1;
                    t.direction2 = e.direction2;
                    t.style = intern(resolve_.text(state, false));
                    emit(s, number, state, std::move(t));
                } else if constexpr (std::is_same_v<E, AnnotationTextElement>) {
                    DrawText t;
                    t.text = e.text;
                    t.position = e.reference;
                    t.annotation = true;
                    t.annotationOffset = e.offset;
                    t.style = intern(resolve_.text(state, true));
                    // Styles past LEAD LINE draw as UNCONNECTED, as a workstation without them does.
                    if (state.annoStyle == 2) t.leadLine = *line(state);
                    emit(s, number, state, std::move(t));
                } else if constexpr (std::is_same_v<E, CellArrayElement>) {
                    // P, Q, R: P and Q opposite corners (2D), or P, Q along the first row, R along
                    // the first column (3D).
                    glm::dvec3 du = e.twoD ? glm::dvec3(e.q.x - e.p.x, 0, 0) : e.q - e.p;
                    glm::dvec3 dv = e.twoD ? glm::dvec3(0, e.q.y - e.p.y, 0) : e.r - e.p;
                    cellArray(s, serial, number, state, {e.p, du, dv, e.columns, e.rows},
                              [&](std::size_t k) { return Colour::indexed(e.colourIndices[k]); });
                } else if constexpr (std::is_same_v<E, CellArrayPlusElement>) {
                    cellArray(s, serial, number, state, {e.p, e.q - e.p, e.r - e.p, e.columns, e.rows},
                              [&](std::size_t k) { return e.colours[k]; });
                } else if constexpr (std::is_same_v<E, PolylineSetWithDataElement>) {
                    polylineSet(s, number, state, e);
                } else if constexpr (std::is_same_v<E, SetOfFillAreaSetsElement>) {
                    for (std::size_t k = 0; k < e.sets.size(); ++k) fillAreaSetOfSet(s, number, state, e, k);
                } else if constexpr (std::is_same_v<E, NurbsCurveElement>) {
                    curve(
                        s, serial, number, state, [&] { return e.curve; }, e.rangeStart, e.rangeEnd);
                } else if constexpr (std::is_same_v<E, GdpElement>) {
                    // Registered GDPs draw as exact curves (the store refused bad points at
                    // insert); the others are ignored (ISO 9592).
                    if (isRegisteredGdp(e.identifier))
                        curve(
                            s, serial, number, state, [&] { return *gdpCurve(e); }, 0.0, 0.0);
                } else if constexpr (std::is_same_v<E, NurbsSurfaceElement>) {
                    ApproximationAttribute a = resolve_.surfaceApproximation(state);
                    const SurfaceCharacteristicsAttribute& c = state.surfaceCharacteristics;
                    TessellationCache::Key key{serial,  a.criteria, a.valueU,  a.valueV,
                                               c.style, c.curvesU,  c.curvesV, 0};
                    key.isoPlacement = c.placement;
                    const std::vector<glm::dvec4> planes = detail::levelPlanes(c, state.composite);
                    for (const glm::dvec4& p : planes)
                        key.levelPlanes.insert(key.levelPlanes.end(), {p.x, p.y, p.z, p.w});
                    const auto& entry = cache_.get(key, TessellationCache::Kind::Surface, [&] {
                        TessellationCache::Entry built;
                        // The store's own surface, shared: no copy per tessellation.
                        auto box = s.elements.shared<NurbsSurfaceElement>(index);
                        built.surface = std::shared_ptr<const geom::Surface>(box, &box->surface);
                        MeshData mesh = detail::tessellateSurface(e, a, c, &cache_);
                        detail::addLevelCurves(mesh, planes, built.surface.get());
                        built.mesh = std::make_shared<const MeshData>(std::move(mesh));
                        return built;
                    });
                    emit(s, number, state,
                         DrawMesh{entry.mesh, entry.surface, interior(state), edge(state), line(state)});
                } else if constexpr (std::is_same_v<E, TriangleStripElement>) {
                    if (e.points.size() < 3) return;
                    facetedMesh(s, serial, number, state, e, [&](detail::FacetMeshInput in) {
                        return detail::stripTriangles(std::move(in));
                    });
                } else if constexpr (std::is_same_v<E, QuadrilateralMeshElement>) {
                    if (e.rows < 2 || e.columns < 2) return;
                    facetedMesh(s, serial, number, state, e, [&](detail::FacetMeshInput in) {
                        return detail::gridTriangles(std::move(in), e.rows, e.columns);
                    });
                } else if constexpr (std::is_same_v<E, IndexAttribute>) {
                    applyIndex(state, e);
                } else if constexpr (std::is_same_v<E, RealAttribute>) {
                    applyReal(state, e);
                } else if constexpr (std::is_same_v<E, ColourAttribute>) {
                    applyColour(state, e);
                } else if constexpr (std::is_same_v<E, UpVectorAttribute>) {
                    (e.type == ElementType::CharacterUpVector ? state.up : state.annoUp) = e.up;
                } else if constexpr (std::is_same_v<E, AlignmentAttribute>) {
                    if (e.type == ElementType::TextAlignment)
                        state.hAlign = e.horizontal, state.vAlign = e.vertical;
                    else
                        state.annoH = e.horizontal, state.annoV = e.vertical;
                } else if constexpr (std::is_same_v<E, AreaPropertiesAttribute>) {
                    (e.type == ElementType::AreaProperties ? state.properties : state.backProperties) = e;
                } else if constexpr (std::is_same_v<E, PatternAttribute>) {
                    applyPattern(state, e);
                } else if constexpr (std::is_same_v<E, AsfAttribute>) {
                    state.individual[static_cast<std::size_t>(e.aspect)] = e.individual;
                } else if constexpr (std::is_same_v<E, ApproximationAttribute>) {
                    (e.type == ElementType::CurveApproximationCriteria ? state.curveApproximation
                                                                       : state.surfaceApproximation) = e;
                } else if constexpr (std::is_same_v<E, SurfaceCharacteristicsAttribute>) {
                    state.surfaceCharacteristics = e;
                } else if constexpr (std::is_same_v<E, LightSourceStateAttribute>) {
                    for (int i : e.deactivate) state.lights.erase(i);
                    for (int i : e.activate) state.lights.insert(i);
                } else if constexpr (std::is_same_v<E, TransformElement>) {
                    using T = ElementType;
                    if (e.type == T::LocalModellingTransformation3 ||
                        e.type == T::LocalModellingTransformation)
                        state.local = compose(state.local, e);
                    else
                        state.global = e.matrix;
                    state.composite = state.global * state.local;
                } else if constexpr (std::is_same_v<E, ModelClipElement>) {
                    // Half spaces are given in modelling coordinates and fixed in the world by the
                    // composite transform current when the element is traversed.
                    const glm::dmat4& m = state.composite;
                    glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(m)));
                    if (e.op == 1) state.clipVolume.clear();
                    for (const auto& [point, normal] : e.halfSpaces) {
                        glm::dvec3 p = glm::dvec3(m * glm::dvec4(point, 1.0));
                        glm::dvec3 n = normalMatrix * normal;
                        state.clipVolume.push_back(glm::dvec4(n, -glm::dot(n, p)));
                    }
                } else if constexpr (std::is_same_v<E, RestoreModelClipElement>) {
                    state.clipVolume = state.inheritedClipVolume;
                } else if constexpr (std::is_same_v<E, NameSetElement>) {
                    for (int n : e.names)
                        if (e.add)
                            state.names.insert(n);
                        else
                            state.names.erase(n);
                }
                // labels, application data and GSEs (none registered) do not change the draw list
            },
            s.elements, index);
    }

    // A curve primitive, tessellated once per element and approximation; `build` makes the
    // exact curve on a cache miss.
    template <class Build>
    void curve(const Structure& s, std::uint64_t serial, int number, const State& state, Build build,
               double rangeStart, double rangeEnd) {
        const ApproximationAttribute a = resolve_.curveApproximation(state);
        TessellationCache::Key key{serial, a.criteria, a.valueU, 0, 0, 0, 0, 0};
        const auto& entry = cache_.get(key, TessellationCache::Kind::Curve, [&] {
            TessellationCache::Entry built;
            built.curveRuns = detail::curveRuns(build(), rangeStart, rangeEnd, a.criteria, a.valueU);
            return built;
        });
        for (const TessellationCache::CurveRun& run : entry.curveRuns)
            emit(s, number, state,
                 DrawCurve{segmentPoints(run.points), run.curve, line(state), run.start, run.end});
    }

    // A zero size component, a zero vector or parallel vectors leave the placement as it was:
    // no pattern box could be formed from them.
    static void applyPattern(State& state, const PatternAttribute& e) {
        PatternPlacement& p = state.pattern;
        if (e.type == ElementType::PatternSize) {
            if (e.size.x != 0.0 && e.size.y != 0.0) p.size = glm::abs(e.size);
            return;
        }
        if (glm::length(glm::cross(e.vectorX, e.vectorY)) <= 0.0) return;
        p.referencePoint = e.referencePoint;
        p.vectorX = e.vectorX;
        p.vectorY = e.vectorY;
    }

    void fillStyle(DrawFillArea& f, const State& state) {
        f.interior = interior(state);
        f.edges = edge(state);
    }
    /// `interior` with a facet's own colour.
    ItemRef<InteriorStyleSet> facetColoured(InteriorStyleSet interior, const Colour& colour,
                                            const State& state) {
        interior.colour = resolve_.rgb(colour, state);
        return intern(interior);
    }

    /// A triangle strip or quadrilateral mesh `e` as a mesh: `triangulate` adds its triangles and
    /// their facets to the input. The colours in use (vertex, else facet; facet alone when flat
    /// shaded) key the cache.
    template <class Mesh, class Triangulate>
    void facetedMesh(const Structure& s, std::uint64_t serial, int number, const State& state, const Mesh& e,
                     Triangulate triangulate) {
        const bool byVertex = !e.vertexColours.empty() && !flatShaded(*interior(state));
        const std::vector<Colour>& used = byVertex ? e.vertexColours : e.facetColours;
        const int variant = !byVertex && !e.vertexColours.empty() ? 1 : 0;
        auto mesh = cachedMesh(serial, state, used, variant, [&] {
            const std::vector<glm::vec3> vertexColours =
                byVertex ? resolveColours(e.vertexColours, state) : std::vector<glm::vec3>{};
            const std::vector<glm::vec3> facetColours =
                byVertex ? std::vector<glm::vec3>{} : resolveColours(e.facetColours, state);
            return detail::facetMesh(triangulate(detail::FacetMeshInput{
                e.points, vertexColours, e.vertexNormals, facetColours, e.facetNormals, {}, {}}));
        });
        emit(s, number, state, DrawMesh{mesh, nullptr, interior(state), edge(state), line(state)});
    }

    /// The cache key of a mesh whose colours are resolved at build: they depend on the tables
    /// when one is indexed or the colour mapping entry changes colours (its index is part of
    /// the key then).
    /// `variant` tells apart meshes of one element built with different colours (1: its facet
    /// colours in place of its vertex colours, for flat shading).
    TessellationCache::Key meshKey(std::uint64_t serial, const State& state, bool indexed, bool coloured,
                                   int variant = 0) const {
        const bool mapped = coloured && resolve_.maps(state.colourMapIndex);
        return {serial, variant,
                0,      0,
                0,      mapped ? state.colourMapIndex : 0,
                0,      indexed || mapped ? tables_.generation + 1 : 0};
    }

    template <class Build>
    std::shared_ptr<const MeshData> cachedMesh(std::uint64_t serial, const State& state,
                                               const std::vector<Colour>& colours, int variant, Build build) {
        TessellationCache::Key key = meshKey(serial, state, anyIndexed(colours), !colours.empty(), variant);
        return cache_
            .get(key, TessellationCache::Kind::Mesh,
                 [&] {
                     TessellationCache::Entry entry;
                     entry.mesh = std::make_shared<const MeshData>(build());
                     return entry;
                 })
            .mesh;
    }

    /// Where the cells of a cell array lie: corner `p`, a row along `du`, a column along `dv`.
    struct CellGrid {
        glm::dvec3 p, du, dv;
        int columns, rows;
    };

    /// A cell array as a mesh of coloured quadrilaterals; `colourOf(k)` is cell k's colour (row by
    /// row). The colours depend on the colour table and the mapping entry, so the key does too.
    template <class ColourOf>
    void cellArray(const Structure& s, std::uint64_t serial, int number, const State& state,
                   const CellGrid& g, ColourOf colourOf) {
        if (g.columns < 1 || g.rows < 1) return;
        const TessellationCache::Key key = meshKey(serial, state, true, true);
        auto mesh = cache_
                        .get(key, TessellationCache::Kind::Mesh,
                             [&] {
                                 MeshData m;
                                 for (int r = 0; r < g.rows; ++r)
                                     for (int c = 0; c < g.columns; ++c) {
                                         glm::vec3 colour = resolve_.rgb(
                                             colourOf(static_cast<std::size_t>(r * g.columns + c)), state);
                                         auto base = static_cast<std::uint32_t>(m.positions.size());
                                         for (auto [a, b] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
                                             glm::dvec3 p = g.p + g.du * (double(c + a) / g.columns) +
                                                            g.dv * (double(r + b) / g.rows);
                                             m.positions.push_back(glm::vec3(p));
                                             m.colours.push_back(colour);
                                         }
                                         m.triangles.insert(m.triangles.end(), {base, base + 1, base + 2,
                                                                                base, base + 2, base + 3});
                                     }
                                 m.trianglesPerFacet = 2;  // a cell's diagonal is no edge
                                 TessellationCache::Entry entry;
                                 entry.mesh = std::make_shared<const MeshData>(std::move(m));
                                 return entry;
                             })
                        .mesh;
        InteriorStyleSet solid = resolve_.interior(state);
        solid.style = InteriorStyle::Solid;
        emit(s, number, state, DrawMesh{mesh, nullptr, intern(solid), intern(EdgeStyle{}), line(state)});
    }

    /// POLYLINE SET 3 WITH DATA: a polyline per member; with vertex colours a segment takes the
    /// colour of its first vertex (polyline shading NONE, ISO/IEC 9592-4), or with polyline
    /// shading COLOUR goes linearly between its vertices' colours. One item per member, so that
    /// its line type runs on along the whole polyline.
    void polylineSet(const Structure& s, int number, const State& state,
                     const PolylineSetWithDataElement& e) {
        const bool shaded = resolve_.lineShaded(state);
        for (std::size_t i = 0; i < e.polylines.size(); ++i) {
            const auto& points = e.polylines[i];
            if (points.size() < 2) continue;
            // A view of the interned style each (a copy of one view would be a copy of its own).
            DrawPolyline p{segmentPoints(points), line(state)};
            if (e.vertexColours.empty())
                emit(s, number, state, std::move(p));
            else
                emit(s, number, state,
                     DrawColouredPolyline{std::move(p),
                                          VertexColours{resolveColours(e.vertexColours[i], state), shaded}});
        }
    }

    /// Set `k` of a SET OF FILL AREA SETS 3 WITH DATA as one fill area set (contours of fewer than
    /// three vertices dropped). With edge data, the edges whose flag is on are drawn as polylines in
    /// the edge style (when the edge flag is on) and the fill area draws none itself.
    void fillAreaSetOfSet(const Structure& s, int number, const State& state,
                          const SetOfFillAreaSetsElement& e, std::size_t k) {
        DrawFillArea f;
        fillStyle(f, state);
        const bool edgeData = !e.edgeFlags.empty() && f.edges->visible;
        const bool vertexColours = !e.vertexColours.empty() && !flatShaded(*f.interior);
        std::vector<std::vector<glm::dvec3>> edges;
        for (std::size_t c = 0; c < e.sets[k].size(); ++c) {
            const std::vector<int>& contour = e.sets[k][c];
            if (contour.size() < 3) continue;
            std::vector<glm::dvec3> points;
            std::vector<Colour> colours;
            std::vector<glm::dvec3> normals;
            for (int v : contour) {
                const auto i = static_cast<std::size_t>(v);
                points.push_back(e.vertices[i]);
                if (vertexColours) colours.push_back(e.vertexColours[i]);
                if (!e.vertexNormals.empty()) normals.push_back(e.vertexNormals[i]);
            }
            if (edgeData) visibleEdges(points, e.edgeFlags[k][c], edges);
            f.contours.push_back(std::move(points));
            if (!colours.empty()) f.vertexColours.push_back(resolveColours(colours, state));
            if (!normals.empty()) f.vertexNormals.push_back(std::move(normals));
        }
        if (f.contours.empty()) return;
        if (!e.facetColours.empty()) f.interior = facetColoured(*f.interior, e.facetColours[k], state);
        if (!e.facetNormals.empty()) f.facetNormal = e.facetNormals[k];
        emitWithEdges(s, number, state, std::move(f), edgeData, edges);
    }

    /// A fill area; with edge data (`edgeData`) it draws no edges itself and its edges whose flag
    /// is on (`edges`, open polylines) follow as polylines in its edge style.
    void emitWithEdges(const Structure& s, int number, const State& state, DrawFillArea&& f, bool edgeData,
                       const std::vector<std::vector<glm::dvec3>>& edges) {
        const EdgeStyle edgeStyle = *f.edges;
        if (edgeData) f.edges = intern(EdgeStyle{false, edgeStyle.colour, edgeStyle.type, edgeStyle.width});
        emit(s, number, state, std::move(f));
        for (const auto& line : edges)
            emit(s, number, state,
                 DrawPolyline{segmentPoints(line),
                              intern(LineStyle{edgeStyle.colour, edgeStyle.type, edgeStyle.width})});
    }

    /// The runs of edges of a closed contour whose flag is on, as open polylines (edge j runs from
    /// vertex j to vertex j + 1, the last back to the first).
    static void visibleEdges(const std::vector<glm::dvec3>& points, const std::vector<int>& flags,
                             std::vector<std::vector<glm::dvec3>>& out) {
        const std::size_t n = points.size();
        std::size_t first = 0;  // start after an off edge, so a run never wraps mid-way
        while (first < n && flags[first] != 0) ++first;
        if (first == n) {  // every edge on: one closed polyline
            out.emplace_back(points).push_back(points[0]);
            return;
        }
        std::vector<glm::dvec3> run;
        for (std::size_t step = 1; step <= n; ++step) {
            const std::size_t j = (first + step) % n;
            if (flags[j] != 0) {
                if (run.empty()) run.push_back(points[j]);
                run.push_back(points[(j + 1) % n]);
            } else if (!run.empty()) {
                out.push_back(std::move(run));
                run.clear();
            }
        }
        if (!run.empty()) out.push_back(std::move(run));
    }

    const StructureStore& store_;
    const WorkstationTables& tables_;
    const TraversalFilters& filters_;
    TessellationCache& cache_;
    DrawList& out_;
    Resolver resolve_;
    std::vector<DrawPathLevel> path_;
    std::map<std::set<int>, int> lightSets_;    ///< this traversal's answers of itemTables_
    std::pair<int, int> lastCue_{INT_MIN, -1};  ///< depth cue index and its answer, this traversal
    Traverser::SubtreeCache* subtrees_;
    Traverser::ItemTables& itemTables_;
    Traverser::RunSizes& runSizes_;
    detail::SegmentPool& segmentPool_;
    std::uint64_t baseStamp_;
    std::shared_ptr<DrawSegment> segment_;  ///< the segment being built
    StylePool& styles_ = *itemTables_.styles;
    std::uint64_t epoch_ = 1;  ///< changes whenever the state may have changed
    Resolved<LineStyle> line_;
    std::array<LineMemo, 64> lineMemo_{};  ///< by a hash of the inputs
    Resolved<MarkerStyle> marker_;
    Resolved<InteriorStyleSet> interior_;
    Resolved<EdgeStyle> edge_;
    const glm::dmat4* transform_ = nullptr;     ///< the segment's record of the last transform
    std::uint64_t transformEpoch_ = 0;          ///< the state transform_ was last compared with
    ItemFields fields_;                         ///< the last state's item fields
    std::span<const glm::dvec4> clip_;          ///< the segment's copy of the last clipping volume
    const DrawContext* context_ = nullptr;      ///< the current state's context (null: invisible)
    const DrawContext* lastContext_ = nullptr;  ///< the segment's last context record
    std::uint64_t contextEpoch_ = 0;            ///< the state context_ was made for
};

}  // namespace

Traverser::Traverser()
    : subtrees_(std::make_unique<SubtreeCache>()),
      itemTables_(std::make_unique<ItemTables>()),
      runSizes_(std::make_unique<RunSizes>()),
      segmentPool_(std::make_shared<detail::SegmentPool>()) {
}

Traverser::~Traverser() {
    segmentPool_->close();
}

void Traverser::setIncremental(bool incremental) {
    if (incremental && !subtrees_) subtrees_ = std::make_unique<SubtreeCache>();
    if (!incremental) subtrees_.reset();
}

DrawList Traverser::traverse(const StructureStore& store, const std::vector<int>& roots,
                             const WorkstationTables& tables, const TraversalFilters& filters) {
    DrawList out;
    for (const ViewRepresentation& v : tables.views.entries())
        out.views.push_back(
            {v.orientation, v.mapping, v.clipMin, v.clipMax, v.clipXY, v.clipBack, v.clipFront});
    out.windowMin = tables.windowMin;
    out.windowMax = tables.windowMax;
    out.viewportMin = tables.viewportMin;
    out.viewportMax = tables.viewportMax;
    out.displaySize = tables.displaySize;
    out.viewInputPriority = tables.views.inputPriority();
    out.background = glm::vec3(tables.colours.get(0));
    out.hiddenSurfaceRemoval = tables.hlhsrMode != 0;
    if (itemTables_->full()) {
        *itemTables_ = {};
        if (subtrees_) subtrees_->clear();
    }
    Walk walk(store, tables, filters, cache_, subtrees_.get(), *itemTables_, *runSizes_, *segmentPool_, out);
    walk.maxPictureBytes = maxPictureBytes_;
    try {
        try {
            for (int root : roots) walk.root(root);
        } catch (const std::bad_alloc&) {  // the picture is dropped whole: the error says why
            throw Error(errors::StorageOverflow, "TRAVERSAL", "out of memory making the picture");
        }
    } catch (...) {
        // A refused picture (too large, too deep) keeps nothing it made: not its segments in the
        // subtree cache, nor spare ones in the pool.
        walk.abandon();
        out.items.clear();
        if (subtrees_) subtrees_->clear();
        segmentPool_->takenSince();  // the next traversal's count starts afresh
        segmentPool_->settle(kSpareSegments);
        throw;
    }
    out.lightSets = itemTables_->lightSets;
    out.depthCues = itemTables_->depthCues;
    elementsTraversed_ = walk.visited;
    elementsReused_ = walk.reused;
    // The subtrees no longer drawn give their segments back first; then free segments this
    // traversal did not need are not kept for the next (a smaller picture), and the kept ones let
    // go of their old items before the cache counts what is drawn.
    if (subtrees_) subtrees_->prune(out.items);
    segmentPool_->settle(segmentPool_->takenSince() + kSpareSegments);
    cache_.prune();
    return out;
}

}  // namespace phigs
