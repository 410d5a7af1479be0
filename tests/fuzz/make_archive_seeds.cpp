// Writes the archive target's seeds into the directory given: small random networks holding
// every element type (tests/phigs/RandomElements.h, as the archive tests make them) and the
// structures of the small model in tests/fuzz/data as the session's FILE > ARCHIVE writes them.
#include "RandomElements.h"
#include "acsynt/session/Session.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/store/ArchiveFile.h"

#include <fstream>
#include <iostream>

namespace {

void writeRandom(const std::filesystem::path& file, unsigned seed) {
    std::mt19937 rng(seed);
    const int structures = 4;
    std::map<int, std::vector<phigs::Element>> contents;
    for (int id = 1; id <= structures; ++id)
        for (int i = 0; i < 12; ++i)
            contents[id].push_back(phigs::testing::randomElement(rng, id, structures));
    std::ofstream(file, std::ios::binary) << phigs::ArchiveFile::encode(contents);
}

void writeModel(const std::filesystem::path& directory) {
    phigs::ScriptInputSource script(
        "choice FILE\nchoice READ_MODEL\nstring small.acm\nchoice ARCHIVE\nstring model.phar\n", "seeds");
    acsynt::SessionSettings settings;
    settings.outputDirectory = directory;
    settings.searchPath = {FUZZ_DATA_DIR};
    acsynt::Session session(settings, script);
    session.run();
    if (!std::filesystem::exists(directory / "model.phar"))
        throw std::runtime_error("the session wrote no archive: " + session.message());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: fuzz_archive_seeds DIRECTORY\n";
        return 2;
    }
    const std::filesystem::path directory = argv[1];
    std::filesystem::create_directories(directory);
    for (unsigned seed = 1; seed <= 3; ++seed)
        writeRandom(directory / ("random_" + std::to_string(seed) + ".phar"), seed);
    writeModel(directory);
    return 0;
}
