#include "acsynt/Model.h"

#include "acsynt/ModelFile.h"

#include <exception>

namespace acsynt {

const Component* Model::find(const std::string& componentName) const {
    for (const Component& c : components)
        if (c.name == componentName) return &c;
    return nullptr;
}

Component* Model::find(const std::string& componentName) {
    for (Component& c : components)
        if (c.name == componentName) return &c;
    return nullptr;
}

std::size_t Model::patchCount() const {
    std::size_t n = 0;
    for (const Component& c : components) n += c.patches.size();
    return n;
}

Model buildModel(const AircraftDescription& description, const std::string& fileName) {
    Model m;
    m.name = description.name;
    m.description = description;
    for (const ComponentDescription& d : description.components) {
        try {
            SectionGrid sections = componentSections(d);
            if (!d.mirrorName.empty()) {
                SectionGrid image = mirrored(sections);
                m.components.push_back(loftComponent(d.name, d.kind, d.colour, std::move(sections)));
                m.components.push_back(loftComponent(d.mirrorName, d.kind, d.colour, std::move(image)));
            } else {
                m.components.push_back(loftComponent(d.name, d.kind, d.colour, std::move(sections)));
            }
        } catch (const std::exception& e) {
            throw ModelFileError(fileName, d.line,
                                 "component '" + d.name + "' cannot be lofted: " + e.what());
        }
    }
    return m;
}

Model loadModel(const std::filesystem::path& path) {
    Model m = buildModel(readAircraftDescription(path), path.string());
    m.sourceFile = path.string();
    return m;
}

}  // namespace acsynt
