// OPEN WORKSTATION through the output registry: the type's factory makes the output the
// workstation owns, refusals become PHIGS errors, CLOSE WORKSTATION hands over the last picture.
#include "ErrorNumber.h"
#include "phigs/Phigs.h"

#include <catch2/catch.hpp>

#include <stdexcept>

namespace test_ws_outputs {

using namespace phigs;
using phigs::test::errorOf;

namespace {

/// What an in-memory output saw.
struct Record {
    int made = 0, presented = 0, closed = 0, destroyed = 0;
    std::size_t lastItems = 0;
    std::string connection;
};

class MemoryOutput : public WorkstationOutput {
public:
    explicit MemoryOutput(Record& record) : record_(record) {}
    ~MemoryOutput() override { ++record_.destroyed; }
    bool present(const DrawList& picture) override {
        ++record_.presented;
        record_.lastItems = picture.items.size();
        return true;
    }
    DrawableSize drawableSize() const override { return {640, 480}; }
    void close(const DrawList& picture) override {
        ++record_.closed;
        record_.lastItems = picture.items.size();
        if (record_.connection == "unwritable") throw std::runtime_error("cannot write unwritable");
    }

private:
    Record& record_;
};

/// A polyline in structure 1.
void drawSomething(Phigs& phigs) {
    StructureStore& store = phigs.store();
    store.openStructure(1);
    store.insert(PolylineElement{{{0, 0, 0}, {1, 1, 0}}});
    store.closeStructure();
}

}  // namespace

TEST_CASE("open workstation makes the output of the type's factory", "[ws][outputs]") {
    Phigs phigs;
    phigs.open();
    drawSomething(phigs);
    Record record;
    phigs.outputs().add(WorkstationType::OffscreenImage, [&](Workstation& ws, const OutputConnection& c) {
        ++record.made;
        record.connection = c.identifier;
        CHECK(ws.type() == WorkstationType::OffscreenImage);
        if (c.identifier.empty()) throw ConnectionRefused("needs a name");
        if (c.identifier == "broken") throw std::runtime_error("no device");
        return std::make_unique<MemoryOutput>(record);
    });
    CHECK(phigs.outputs().types() == std::vector<WorkstationType>{WorkstationType::OffscreenImage});

    OutputConnection named;
    named.identifier = "picture.png";
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage, named);
    CHECK(record.made == 1);
    CHECK(ws.connectionIdentifier() == "picture.png");
    REQUIRE(ws.output() != nullptr);
    CHECK(ws.drawableSize() == DrawableSize{640, 480});
    ws.postStructure(1, 0.5);
    CHECK(ws.present());
    CHECK(record.presented == 1);
    CHECK(record.lastItems == 1);
    phigs.closeWorkstation(1);
    CHECK(record.closed == 1);
    CHECK(record.destroyed == 1);

    SECTION("refusals are PHIGS errors and open nothing") {
        CHECK(errorOf([&] { phigs.openWorkstation(2, WorkstationType::OffscreenImage, {}); }) ==
              errors::ConnectionNotRecognized);
        OutputConnection broken;
        broken.identifier = "broken";
        CHECK(errorOf([&] { phigs.openWorkstation(2, WorkstationType::OffscreenImage, broken); }) ==
              errors::WorkstationCannotOpen);
        CHECK(phigs.openWorkstationIds().empty());
        CHECK(phigs.errorLog().size() >= 2);
        CHECK(phigs.errorLog().entries().back().detail.find("no device") != std::string::npos);
    }
    SECTION("a type that is none is error 52; an identifier in use 53") {
        CHECK(errorOf([&] { phigs.openWorkstation(2, static_cast<WorkstationType>(42), named); }) ==
              errors::BadWorkstationType);
        phigs.openWorkstation(2, WorkstationType::OffscreenImage, named);
        CHECK(errorOf([&] { phigs.openWorkstation(2, WorkstationType::OffscreenImage, named); }) ==
              errors::WorkstationIdInUse);
        CHECK(record.made == 2);  // the refused second open made no output
        phigs.closeWorkstation(2);
    }
    SECTION("an output that cannot write its last picture: 903, and the workstation is closed") {
        OutputConnection unwritable;
        unwritable.identifier = "unwritable";
        phigs.openWorkstation(3, WorkstationType::OffscreenImage, unwritable);
        CHECK(errorOf([&] { phigs.closeWorkstation(3); }) == errors::WriteError);
        CHECK(phigs.openWorkstationIds().empty());
        CHECK(record.destroyed == 2);
    }
    SECTION("a type no library registered opens without an output") {
        Workstation& hardcopy = phigs.openWorkstation(4, WorkstationType::PdfFile, named);
        CHECK(hardcopy.output() == nullptr);
        CHECK_FALSE(hardcopy.present());
        phigs.closeWorkstation(4);
    }
}

}  // namespace test_ws_outputs
