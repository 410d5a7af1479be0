// INCREMENTAL SPATIAL SEARCH (ISO 9592-1, 4.4.6) in the core: where the search starts and ends,
// transforms, executed structures, model clipping and the name-set filters; and, over random
// networks, the same answer as a stateful brute-force traversal written independently.
#include "phigs/pick/SpatialSearch.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <optional>
#include <random>

namespace test_spatial_search {

using namespace phigs;

namespace {

void build(StructureStore& store, int id, std::initializer_list<Element> elements) {
    store.openStructure(id);
    for (const Element& e : elements) store.insert(e);
    store.closeStructure();
}

Element modelClip(glm::dvec3 point, glm::dvec3 normal, int op = 1) {
    return ModelClipElement{op, {{point, normal}}, false};
}
Element clipOn() {
    return IndexAttribute{ElementType::ModelClippingIndicator, 1};
}

// Structure 1: a line on the x axis, a shift up by 5, EXECUTE 2, a marker at x = 10 (y = 5).
// Structure 2: names {1}, a line from x 0 to 1, clipping to x >= 0.5, a short line x 0..0.2.
struct Network {
    StructureStore store;
    Network() {
        build(store, 2,
              {addNamesToSet({1}), polyline3({{0, 0, 0}, {1, 0, 0}}), modelClip({0.5, 0, 0}, {1, 0, 0}),
               clipOn(), polyline3({{0, 0, 0}, {0.2, 0, 0}})});
        build(store, 1,
              {polyline3({{0, 0, 0}, {1, 0, 0}}),
               localTransformation3(glm::translate(glm::dmat4(1.0), {0, 5, 0}), Composition::Replace),
               executeStructure(2), polymarker3({{10, 0, 0}})});
    }
    StructurePath search(SpatialSearchQuery q) const { return incrementalSpatialSearch(store, q, "TEST"); }
};

SpatialSearchQuery near(glm::dvec3 point, double distance, StructurePath start, int ceiling = 1) {
    SpatialSearchQuery q;
    q.point = point;
    q.distance = distance;
    q.start = std::move(start);
    q.ceiling = ceiling;
    return q;
}

}  // namespace

TEST_CASE("spatial search: starts after the start path's element, in world coordinates", "[spatial search]") {
    const Network n;
    CHECK(n.search(near({0.5, 0.05, 0}, 0.1, {{1, 0}})) == StructurePath{{1, 1}});
    CHECK(n.search(near({0.5, 0.05, 0}, 0.1, {{1, 1}})).empty());  // (1, 1) itself is in the setup
    // The line of structure 2 lies at y = 5 through the shift.
    CHECK(n.search(near({0.5, 5, 0}, 0.1, {{1, 1}})) == StructurePath{{1, 3}, {2, 2}});
    CHECK(n.search(near({0.5, 5, 0}, 0.1, {{1, 3}, {2, 0}})) == StructurePath{{1, 3}, {2, 2}});
    CHECK(n.search(near({0.5, 5, 0}, 0.1, {{1, 3}, {2, 2}})).empty());
    // The start path's element is processed in the setup: an executed structure is not searched.
    CHECK(n.search(near({0.5, 5, 0}, 0.1, {{1, 3}})).empty());
    CHECK(n.search(near({10, 5, 0}, 0.1, {{1, 3}})) == StructurePath{{1, 4}});
}

TEST_CASE("spatial search: a distance <= 0 asks for the point itself", "[spatial search]") {
    const Network n;
    CHECK(n.search(near({0.5, 0, 0}, 0.0, {{1, 0}})) == StructurePath{{1, 1}});
    CHECK(n.search(near({0.5, 0, 0}, -1.0, {{1, 0}})) == StructurePath{{1, 1}});
    CHECK(n.search(near({0.5, 0.01, 0}, 0.0, {{1, 0}})).empty());
    CHECK(n.search(near({1.5, 0, 0}, 0.49, {{1, 0}})).empty());
    CHECK(n.search(near({1.5, 0, 0}, 0.51, {{1, 0}})) == StructurePath{{1, 1}});
}

TEST_CASE("spatial search: the ceiling ends the search with its structure", "[spatial search]") {
    const Network n;
    CHECK(n.search(near({10, 5, 0}, 0.1, {{1, 3}, {2, 0}}, 2)).empty());
    CHECK(n.search(near({10, 5, 0}, 0.1, {{1, 3}, {2, 0}}, 1)) == StructurePath{{1, 4}});
}

TEST_CASE("spatial search: model clipping cuts the loci when asked", "[spatial search]") {
    const Network n;
    SpatialSearchQuery q = near({0.1, 5, 0}, 0.05, {{1, 3}, {2, 2}});
    CHECK(n.search(q) == StructurePath{{1, 3}, {2, 5}});  // the short line, unclipped
    q.modelClip = true;
    CHECK(n.search(q).empty());  // clipped away: it lies at x < 0.5
    q.point = {0.6, 5, 0};
    q.distance = 0.45;  // reaches the clipped-away line's end at x = 0.2 only without clipping
    CHECK(n.search(q).empty());
    q.modelClip = false;
    CHECK(n.search(q) == StructurePath{{1, 3}, {2, 5}});
}

TEST_CASE("spatial search: normal filters must all accept, inverted ones all reject", "[spatial search]") {
    const Network n;
    SpatialSearchQuery q = near({0.5, 2.5, 0}, 3.0, {{1, 0}});  // reaches both long lines
    CHECK(n.search(q) == StructurePath{{1, 1}});
    q.normal = {NameSetFilter{{1}, {}}};
    CHECK(n.search(q) == StructurePath{{1, 3}, {2, 2}});  // (1, 1) has an empty name set
    q.normal.push_back(NameSetFilter{{1}, {1}});
    CHECK(n.search(q).empty());
    q.normal = {};
    q.inverted = {NameSetFilter{{1}, {}}};
    CHECK(n.search(q) == StructurePath{{1, 1}});
    q.start = {{1, 1}};
    CHECK(n.search(q).empty());  // the line of structure 2 carries name 1
}

TEST_CASE("spatial search: a start path not in the CSS is 203, a ceiling outside it 204",
          "[spatial search]") {
    const Network n;
    auto error = [&](SpatialSearchQuery q) {
        try {
            n.search(q);
        } catch (const Error& e) {
            return e.number();
        }
        return 0;
    };
    CHECK(error(near({0, 0, 0}, 1, {})) == 203);
    CHECK(error(near({0, 0, 0}, 1, {{9, 0}})) == 203);
    CHECK(error(near({0, 0, 0}, 1, {{1, 5}})) == 203);
    CHECK(error(near({0, 0, 0}, 1, {{1, 2}, {2, 0}})) == 203);  // (1, 2) executes nothing
    CHECK(error(near({0, 0, 0}, 1, {{1, 0}, {2, 0}})) == 203);
    CHECK(error(near({0, 0, 0}, 1, {{1, 3}, {2, 6}})) == 203);
    CHECK(error(near({0, 0, 0}, 1, {{1, 0}}, 0)) == 204);
    CHECK(error(near({0, 0, 0}, 1, {{1, 3}, {2, 0}}, 3)) == 204);
}

namespace {

// ---- the brute force: a stateful conceptual traversal over the few element kinds below.

struct State {
    glm::dmat4 global{1.0}, local{1.0};
    std::set<int> names;
    std::vector<glm::dvec4> planes;  // world coordinates
    bool clip = false;
};

double segmentDistance(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b, const std::vector<glm::dvec4>& planes) {
    double t0 = 0, t1 = 1;
    for (const auto& h : planes) {
        const double da = glm::dot(glm::dvec3(h), a) + h.w, db = glm::dot(glm::dvec3(h), b) + h.w;
        if (da < 0 && db < 0) return 1e300;
        if (da < 0) t0 = std::max(t0, da / (da - db));
        if (db < 0) t1 = std::min(t1, da / (da - db));
    }
    if (t0 > t1) return 1e300;
    const glm::dvec3 d = b - a;
    const double t = glm::dot(d, d) > 0 ? std::clamp(glm::dot(p - a, d) / glm::dot(d, d), t0, t1) : t0;
    return glm::length(a + d * t - p);
}

class BruteForce {
public:
    BruteForce(const StructureStore& store, const SpatialSearchQuery& q) : store_(store), q_(q) {}

    StructurePath run() {
        walk(q_.start[0].structureId, 0, State{});
        return found_;
    }

private:
    bool onStart(std::size_t depth) const {
        if (depth >= q_.start.size()) return false;
        for (std::size_t i = 0; i < depth; ++i)
            if (path_[i] != q_.start[i]) return false;
        return true;
    }

    // Returns true when the search is over.
    bool walk(int id, std::size_t depth, State s) {
        path_.resize(depth + 1);
        if (onStart(depth) && depth + 1 == q_.start.size() && q_.start.back().elementNumber == 0)
            searching_ = true;
        const int count = store_.elementCount(id);
        for (int k = 1; k <= count; ++k) {
            path_.resize(depth + 1);
            path_[depth] = {id, k};
            if (element(store_.elementAt(id, k), depth, s)) return true;
            path_.resize(depth + 1);
            if (path_ == q_.start) searching_ = true;
        }
        // The end of the ceiling's structure on the start path ends the search.
        return searching_ && onStart(depth) && depth + 1 == static_cast<std::size_t>(q_.ceiling);
    }

    bool element(const Element& e, std::size_t depth, State& s) {
        const glm::dmat4 m = s.global * s.local;
        if (const auto* t = std::get_if<TransformElement>(&e)) {
            s.local = t->composition == Composition::Replace          ? t->matrix
                      : t->composition == Composition::Preconcatenate ? s.local * t->matrix
                                                                      : t->matrix * s.local;
        } else if (const auto* n = std::get_if<NameSetElement>(&e)) {
            for (int name : n->names) n->add ? void(s.names.insert(name)) : void(s.names.erase(name));
        } else if (const auto* c = std::get_if<ModelClipElement>(&e)) {
            if (c->op == 1) s.planes.clear();
            for (const auto& [p, normal] : c->halfSpaces)
                s.planes.push_back(glm::transpose(glm::inverse(m)) *
                                   glm::dvec4(normal, -glm::dot(normal, p)));
        } else if (const auto* index = std::get_if<IndexAttribute>(&e)) {
            if (index->type == ElementType::ModelClippingIndicator) s.clip = index->value == 1;
        } else if (const auto* x = std::get_if<ExecuteStructureElement>(&e)) {
            State child = s;
            child.global = m;
            child.local = glm::dmat4(1.0);
            if (walk(x->structureId, depth + 1, child)) return true;
        } else if (searching_) {
            std::vector<glm::dvec3> points;
            bool line = false;
            if (const auto* l = std::get_if<PolylineElement>(&e)) points = l->points.toVector(), line = true;
            if (const auto* mk = std::get_if<PolymarkerElement>(&e)) points = mk->points.toVector();
            double best = 1e300;
            const std::vector<glm::dvec4> none;
            const auto& planes = q_.modelClip && s.clip ? s.planes : none;
            for (std::size_t i = 0; i < points.size(); ++i) {
                const glm::dvec3 a = glm::dvec3(m * glm::dvec4(points[i], 1));
                const glm::dvec3 b =
                    line && i + 1 < points.size() ? glm::dvec3(m * glm::dvec4(points[i + 1], 1)) : a;
                if (line && i + 1 == points.size()) break;
                best = std::min(best, segmentDistance(q_.point, a, b, planes));
            }
            const bool filters = std::all_of(q_.normal.begin(), q_.normal.end(),
                                             [&](auto& f) { return f.accepts(s.names); }) &&
                                 std::none_of(q_.inverted.begin(), q_.inverted.end(),
                                              [&](auto& f) { return f.accepts(s.names); });
            if (best <= std::max(q_.distance, 0.0) && filters) {
                found_ = path_;
                return true;
            }
        }
        return false;
    }

    const StructureStore& store_;
    const SpatialSearchQuery& q_;
    StructurePath path_, found_;
    bool searching_ = false;
};

// Every element position a traversal visits from `id` (candidate start paths).
void positions(const StructureStore& store, int id, StructurePath prefix, std::vector<StructurePath>& out) {
    prefix.push_back({id, 0});
    out.push_back(prefix);
    for (int k = 1; k <= store.elementCount(id); ++k) {
        prefix.back().elementNumber = k;
        out.push_back(prefix);
        if (const auto* x =
                store.structure(id).elements.get<ExecuteStructureElement>(static_cast<std::size_t>(k - 1)))
            positions(store, x->structureId, prefix, out);
    }
}

NameSetFilter randomFilter(std::mt19937& rng) {
    NameSetFilter f;
    for (int name = 1; name <= 3; ++name) {
        if (rng() % 2) f.inclusion.insert(name);
        if (rng() % 4 == 0) f.exclusion.insert(name);
    }
    return f;
}

Element randomElement(std::mt19937& rng, int id, int structures) {
    auto real = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    auto point = [&] { return glm::dvec3(real(-2, 2), real(-2, 2), real(-2, 2)); };
    switch (rng() % 8) {
        case 0:
        case 1:
            return polyline3({point(), point(), point()});
        case 2:
            return polymarker3({point(), point()});
        case 3: {
            glm::dmat4 t = glm::translate(glm::dmat4(1.0), point());
            t = glm::scale(t, glm::dvec3(real(0.5, 2), real(0.5, 2), real(0.5, 2)));
            return localTransformation3(t, static_cast<Composition>(rng() % 3));
        }
        case 4:
            return NameSetElement{rng() % 3 != 0, {static_cast<int>(rng() % 3) + 1}};
        case 5:
            return ModelClipElement{static_cast<int>(rng() % 2) + 1, {{point(), point()}}, false};
        case 6:
            return IndexAttribute{ElementType::ModelClippingIndicator, static_cast<int>(rng() % 2)};
        default:
            return id < structures ? executeStructure(id + 1 + static_cast<int>(rng() % (structures - id)))
                                   : polyline3({point(), point()});
    }
}

}  // namespace

TEST_CASE("spatial search: random networks agree with a brute-force traversal",
          "[spatial search][property]") {
    std::mt19937 rng(20240519);
    int found = 0;
    for (int trial = 0; trial < 300; ++trial) {
        StructureStore store;
        const int structures = 1 + static_cast<int>(rng() % 4);
        for (int id = structures; id >= 1; --id) {
            store.openStructure(id);
            for (int k = 0, n = 2 + static_cast<int>(rng() % 6); k < n; ++k)
                store.insert(randomElement(rng, id, structures));
            store.closeStructure();
        }
        std::vector<StructurePath> starts;
        positions(store, 1, {}, starts);
        for (int query = 0; query < 5; ++query) {
            SpatialSearchQuery q;
            q.point = {std::uniform_real_distribution<double>(-3, 3)(rng),
                       std::uniform_real_distribution<double>(-3, 3)(rng),
                       std::uniform_real_distribution<double>(-3, 3)(rng)};
            q.distance = std::uniform_real_distribution<double>(0.0, 4.0)(rng);
            q.start = starts[rng() % starts.size()];
            q.ceiling = 1 + static_cast<int>(rng() % q.start.size());
            q.modelClip = rng() % 2;
            for (int f = 0, n = static_cast<int>(rng() % 3); f < n; ++f)
                q.normal.push_back(randomFilter(rng));
            for (int f = 0, n = static_cast<int>(rng() % 3); f < n; ++f)
                q.inverted.push_back(randomFilter(rng));
            const StructurePath expected = BruteForce(store, q).run();
            INFO("trial " << trial << " query " << query);
            CHECK(incrementalSpatialSearch(store, q, "TEST") == expected);
            found += !expected.empty();
        }
    }
    CHECK(found > 100);  // the random queries find something often enough to mean something
}

}  // namespace test_spatial_search
