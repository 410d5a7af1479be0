#include "FileEntities.h"

#include <Geom_BSplineSurface.hxx>
#include <IGESData_IGESEntity.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_EntityIterator.hxx>
#include <Interface_Graph.hxx>
#include <StepData_StepModel.hxx>
#include <StepGeom_BSplineSurfaceWithKnots.hxx>
#include <StepGeom_BSplineSurfaceWithKnotsAndRationalBSplineSurface.hxx>
#include <StepGeom_CartesianPoint.hxx>
#include <StepGeom_HArray2OfCartesianPoint.hxx>
#include <StepShape_Face.hxx>
#include <StepShape_OrientedFace.hxx>
#include <TColStd_HArray1OfInteger.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TransferBRep.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>

#include <algorithm>
#include <set>
#include <sstream>

namespace geom::exchange {

namespace {

std::string number(double x) {
    std::ostringstream s;
    s.precision(10);
    s << x;
    return s.str();
}

/// Which rule of a B-spline a STEP B-spline surface breaks, or "": OpenCASCADE says only
/// "Surface has not been created".
std::string stepBSplineProblem(const opencascade::handle<Interface_InterfaceModel>& model,
                               const opencascade::handle<Standard_Transient>& entity) {
    const auto surface = opencascade::handle<StepGeom_BSplineSurface>::DownCast(entity);
    opencascade::handle<StepGeom_BSplineSurfaceWithKnots> knots =
        opencascade::handle<StepGeom_BSplineSurfaceWithKnots>::DownCast(entity);
    if (const auto rational =
            opencascade::handle<StepGeom_BSplineSurfaceWithKnotsAndRationalBSplineSurface>::DownCast(entity))
        knots = rational->BSplineSurfaceWithKnots();
    if (surface.IsNull() || knots.IsNull() || surface->ControlPointsList().IsNull()) return {};
    const opencascade::handle<StepGeom_HArray2OfCartesianPoint> points = surface->ControlPointsList();
    for (int i = points->LowerRow(); i <= points->UpperRow(); ++i)
        for (int j = points->LowerCol(); j <= points->UpperCol(); ++j)
            if (const auto& p = points->Value(i, j); !p.IsNull() && p->NbCoordinates() != 3)
                return "control point " + entityLabel(model, p) + " has " +
                       std::to_string(p->NbCoordinates()) + " coordinates, not 3";
    for (const bool u : {true, false}) {
        const std::string in = u ? " in u" : " in v";
        const int degree = u ? surface->UDegree() : surface->VDegree();
        const long long poles = u ? surface->NbControlPointsListI() : surface->NbControlPointsListJ();
        const opencascade::handle<TColStd_HArray1OfInteger> m =
            u ? knots->UMultiplicities() : knots->VMultiplicities();
        const opencascade::handle<TColStd_HArray1OfReal> k = u ? knots->UKnots() : knots->VKnots();
        if (degree < 1 || degree > Geom_BSplineSurface::MaxDegree())
            return "degree " + std::to_string(degree) + in + " (1 to " +
                   std::to_string(Geom_BSplineSurface::MaxDegree()) + " allowed)";
        if (m.IsNull() || k.IsNull() || m->Length() != k->Length() || k->Length() < 2)
            return "knots and multiplicities" + in + " that do not pair up";
        long long sum = 0;
        for (int i = k->Lower(); i <= k->Upper(); ++i) {
            if (i > k->Lower() && !(k->Value(i) > k->Value(i - 1)))
                return "knots" + in + " not increasing (" + number(k->Value(i - 1)) + " then " +
                       number(k->Value(i)) + ")";
            const int mi = m->Value(i - k->Lower() + m->Lower());
            if (mi < 1 || mi > degree + 1)
                return "a knot multiplicity of " + std::to_string(mi) + in +
                       " (1 to degree + 1 = " + std::to_string(degree + 1) + " allowed)";
            sum += mi;
        }
        if (sum != poles + degree + 1)
            return "knot multiplicities" + in + " adding up to " + std::to_string(sum) + ", not " +
                   std::to_string(poles) + " control points + degree + 1";
    }
    return {};
}

/// OpenCASCADE's class name without its package ("BSplineSurfaceWithKnots"), or the IGES type.
std::string typeOf(const opencascade::handle<Standard_Transient>& entity) {
    if (const auto iges = opencascade::handle<IGESData_IGESEntity>::DownCast(entity))
        return "type " + std::to_string(iges->TypeNumber());
    const std::string name = entity->DynamicType()->Name();
    const std::size_t bar = name.find('_');
    return bar == std::string::npos ? name : name.substr(bar + 1);
}

bool igesFace(int type) {
    return type == 143 || type == 144 || type == 510;
}

bool igesSurface(int type) {
    static const std::set<int> surfaces{114, 118, 120, 122, 128, 140, 190, 192, 194, 196, 198};
    return surfaces.count(type) > 0;
}

/// Is the entity a face of the file's own: a STEP face (not an oriented reference to one), an
/// IGES face, or an IGES surface that no face or curve on a surface takes as its support.
bool isFace(const opencascade::handle<Standard_Transient>& entity, const Interface_Graph& graph) {
    if (opencascade::handle<StepShape_Face>::DownCast(entity))
        return !opencascade::handle<StepShape_OrientedFace>::DownCast(entity);
    const auto iges = opencascade::handle<IGESData_IGESEntity>::DownCast(entity);
    if (iges.IsNull()) return false;
    if (igesFace(iges->TypeNumber())) return true;
    if (!igesSurface(iges->TypeNumber())) return false;
    for (Interface_EntityIterator users = graph.Sharings(entity); users.More(); users.Next()) {
        const auto user = opencascade::handle<IGESData_IGESEntity>::DownCast(users.Value());
        if (!user.IsNull() && (igesFace(user->TypeNumber()) || user->TypeNumber() == 141 ||
                               user->TypeNumber() == 142 || igesSurface(user->TypeNumber())))
            return false;
    }
    return true;
}

}  // namespace

std::string entityLabel(const opencascade::handle<Interface_InterfaceModel>& model,
                        const opencascade::handle<Standard_Transient>& entity) {
    if (const auto iges = opencascade::handle<IGESData_IGESModel>::DownCast(model)) {
        const auto e = opencascade::handle<IGESData_IGESEntity>::DownCast(entity);
        if (!e.IsNull()) return "DE " + std::to_string(iges->DNum(e));
    }
    if (const auto step = opencascade::handle<StepData_StepModel>::DownCast(model))
        return "#" + std::to_string(step->IdentLabel(entity));
    return "entity " + std::to_string(model->Number(entity));
}

std::string FileFaces::labelOf(const TopoDS_Shape& face) const {
    const auto it = labels.find(face.TShape().get());
    return it == labels.end() ? std::string() : it->second;
}

FileFaces fileFaces(const opencascade::handle<XSControl_WorkSession>& session) {
    FileFaces faces;
    const opencascade::handle<Interface_InterfaceModel> model = session->Model();
    const opencascade::handle<XSControl_TransferReader> transfer = session->TransferReader();
    if (model.IsNull() || transfer.IsNull()) return faces;
    const opencascade::handle<Transfer_TransientProcess> process = transfer->TransientProcess();
    if (process.IsNull()) return faces;
    // The first failure noted on each entity.
    std::map<const Standard_Transient*, std::string> failures;
    const Interface_CheckIterator checks = process->CheckList(false);
    for (checks.Start(); checks.More(); checks.Next()) {
        const opencascade::handle<Interface_Check>& check = checks.Value();
        if (check->NbFails() == 0 || check->Entity().IsNull()) continue;
        std::string text = check->CFail(1);
        text.erase(0, std::min(text.find_first_not_of(' '), text.size()));  // some start with a space
        failures.emplace(check->Entity().get(), text);
    }
    const Interface_Graph& graph = session->Graph();
    for (int i = 1; i <= model->NbEntities(); ++i) {
        const opencascade::handle<Standard_Transient> entity = model->Value(i);
        if (!isFace(entity, graph)) continue;
        const std::string label = entityLabel(model, entity);
        const TopoDS_Shape shape = TransferBRep::ShapeResult(process->Find(entity));
        if (!shape.IsNull()) {
            faces.labels.emplace(shape.TShape().get(), label);
            continue;
        }
        // Why: the first failure on the face or what it refers to, nearest first (its surface).
        std::string cause = "OpenCASCADE did not transfer it";
        std::vector<opencascade::handle<Standard_Transient>> level{entity};
        std::set<const Standard_Transient*> seen{entity.get()};
        for (int depth = 0; depth < 8 && !level.empty(); ++depth) {
            const auto found = std::find_if(level.begin(), level.end(),
                                            [&](const auto& e) { return failures.count(e.get()) > 0; });
            if (found != level.end()) {
                const std::string own = stepBSplineProblem(model, *found);
                cause = (*found == entity ? "" : entityLabel(model, *found) + " " + typeOf(*found) + ": ") +
                        (own.empty() ? failures[found->get()] : own);
                break;
            }
            std::vector<opencascade::handle<Standard_Transient>> next;
            for (const auto& e : level)
                for (Interface_EntityIterator it = graph.Shareds(e); it.More(); it.Next())
                    if (seen.insert(it.Value().get()).second) next.push_back(it.Value());
            level = std::move(next);
        }
        faces.lost.push_back(label + ": a face left out: " + cause);
    }
    return faces;
}

}  // namespace geom::exchange
