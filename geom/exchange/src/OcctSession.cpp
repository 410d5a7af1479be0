#include "OcctSession.h"

#include "geom/exchange/CadModel.h"

#include <IGESCAFControl_Writer.hxx>
#include <IGESControl_Controller.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPCAFControl_Controller.hxx>
#include <STEPControl_Controller.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>

namespace geom::exchange {

namespace {

std::mutex& exchangeMutex() {
    static std::mutex m;
    return m;
}

void initialiseOnce() {
    static std::once_flag once;
    std::call_once(once, [] {
        // Reports go to the caller as exceptions and warnings, not to the console.
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
        STEPControl_Controller::Init();
        IGESControl_Controller::Init();
        STEPCAFControl_Controller::Init();
    });
}

}  // namespace

std::unique_lock<std::mutex> OcctSession::lock() {
    return std::unique_lock<std::mutex>(exchangeMutex());
}

OcctSession::OcctSession(const std::string& unitCode, Locking locking) {
    if (locking == Locking::Lock) lock_ = lock();
    initialiseOnce();
    metres_ = metresPerUnit(unitCode).value_or(1.0);
    Interface_Static::SetCVal("xstep.cascade.unit", unitCode.c_str());
    Interface_Static::SetCVal("write.step.unit", unitCode.c_str());
    Interface_Static::SetCVal("write.iges.unit", unitCode.c_str());
    Interface_Static::SetCVal("write.step.schema", "AP214IS");
    Interface_Static::SetIVal("write.iges.brep.mode", 0);  // faces: 144 trimmed surfaces, not 186 solids
    // The IGES reader would split B-splines at C0 or C1 knots into more faces: keep them whole.
    Interface_Static::SetIVal("read.iges.bspline.continuity", 0);
}

OcctSession::~OcctSession() {
    for (const auto& document : documents_)
        if (document->IsOpened()) XCAFApp_Application::GetApplication()->Close(document);
}

opencascade::handle<TDocStd_Document> OcctSession::newDocument() {
    opencascade::handle<TDocStd_Document> document;
    XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", document);
    XCAFDoc_DocumentTool::SetLengthUnit(document, metres_);
    documents_.push_back(document);
    return document;
}

}  // namespace geom::exchange
