#include "app/SeedLaunch.h"

#include "util/DataPaths.h"

#include <istream>
#include <map>
#include <ostream>
#include <stdexcept>

namespace penumbra::app {

namespace {

struct Question {
    const char* title;
    std::vector<const char*> answers;  // answer k is number k + 1
};

// Seed 002's menu, its order and numbering (section 3.3), with what each answer is here.
const Question kScene{"Scene", {"bench in a park (scenes/park.json)", "construction site (scenes/construction.json)",
                                "street (scenes/street.json)"}};
const Question kTechnique{"Shadow technique",
                          {"no shadows (none)", "shadow maps (hard)", "soft shadow maps (pcf-poisson16)",
                           "parallel-split shadow maps (cascaded)", "LiSPSM (lispsm)",
                           "combination of techniques, one per region (street only)"}};
const Question kManipulator{"Camera manipulator", {"trackball", "first person (fly)", "orbit"}};
const char* kSceneFiles[] = {"park.json", "construction.json", "street.json"};
const char* kTechniques[] = {"none", "hard", "pcf-poisson16", "cascaded", "lispsm", ""};
const char* kControllers[] = {"trackball", "fly", "orbit"};

int ask(std::istream& in, std::ostream& out, const Question& q) {
    out << q.title << ":\n";
    for (std::size_t k = 0; k < q.answers.size(); ++k) out << "  " << k + 1 << ". " << q.answers[k] << "\n";
    for (;;) {
        out << "choose 1-" << q.answers.size() << ": " << std::flush;
        std::string line;
        if (!std::getline(in, line)) throw std::runtime_error(std::string("menu: no answer for '") + q.title + "' (end of input)");
        try {
            std::size_t used = 0;
            const int n = std::stoi(line, &used);
            if (line.find_first_not_of(" \t\r", used) == std::string::npos && n >= 1 && n <= static_cast<int>(q.answers.size()))
                return n;
        } catch (const std::exception&) {
        }
        out << "'" << line << "' is not one of the numbers above\n";
    }
}

int askCount(std::istream& in, std::ostream& out, const char* what) {
    return ask(in, out, Question{what, {"1", "2", "3", "4"}});
}

void check(int value, int most, const char* flag) {
    if (value < 0 || value > most)
        throw std::invalid_argument(std::string(flag) + " " + std::to_string(value) + ": expected 1.." + std::to_string(most));
}

}  // namespace

std::vector<std::string> expandSeedFlags(int argc, char** argv) {
    static const std::map<std::string, std::string> kLong = {{"-sc", "--seed-scene"},       {"-sh", "--seed-technique"},
                                                            {"-m", "--seed-manipulator"}, {"-cw", "--tiles-across"},
                                                            {"-ch", "--tiles-down"}};
    std::vector<std::string> args;
    for (int i = 0; i < argc; ++i) {
        const auto it = kLong.find(argv[i]);
        args.emplace_back(i > 0 && it != kLong.end() ? it->second : argv[i]);
    }
    return args;
}

void addSeedChoices(CLI::App& command, SeedChoices& c) {
    const char* group = "seed 002's numbered choices (its -sc -sh -m -cw -ch)";
    command.add_option("--seed-scene,--sc", c.scene, "-sc N: 1 park, 2 construction site, 3 street")->group(group)->check(CLI::Range(1, 3));
    command.add_option("--seed-technique,--sh", c.technique,
                       "-sh N: 1 none, 2 shadow maps, 3 soft, 4 PSSM, 5 LiSPSM, 6 combined (street)")
        ->group(group)->check(CLI::Range(1, 6));
    command.add_option("--seed-manipulator", c.manipulator, "-m N: 1 trackball, 2 first person, 3 orbit")->group(group)->check(CLI::Range(1, 3));
    command.add_option("--tiles-across,--cw", c.tilesAcross, "-cw N: LiSPSM cameras across (1-4)")->group(group)->check(CLI::Range(1, 4));
    command.add_option("--tiles-down,--ch", c.tilesDown, "-ch N: LiSPSM cameras down (1-4)")->group(group)->check(CLI::Range(1, 4));
}

void applySeedChoices(const SeedChoices& c, std::filesystem::path& scene, render::RenderOptions& render, std::string& controller) {
    check(c.scene, 3, "-sc");
    check(c.technique, 6, "-sh");
    check(c.manipulator, 3, "-m");
    check(c.tilesAcross, 4, "-cw");
    check(c.tilesDown, 4, "-ch");
    if (c.scene) scene = paths::dataRoot() / "scenes" / kSceneFiles[c.scene - 1];
    if (c.technique == 6) {  // the scene's regions decide; checked once the scene is loaded
        render.technique.clear();
        render.requireRegions = true;
    } else if (c.technique) {
        render.technique = kTechniques[c.technique - 1];
    }
    if (c.tilesAcross || c.tilesDown) {
        if (render.technique != "lispsm")
            throw std::invalid_argument("-cw/-ch (LiSPSM's cameras across and down) need -sh 5 (LiSPSM)");
        if (c.tilesAcross) render.parameters.emplace_back("cols", std::to_string(c.tilesAcross));
        if (c.tilesDown) render.parameters.emplace_back("rows", std::to_string(c.tilesDown));
    }
    if (c.manipulator) controller = kControllers[c.manipulator - 1];
}

SeedChoices askSeedMenu(std::istream& in, std::ostream& out) {
    out << "penumbra: choose what to open (seed 002's menu; the same as -sc N -sh N -m N on the command line)\n";
    SeedChoices c;
    c.scene = ask(in, out, kScene);
    for (;;) {
        c.technique = ask(in, out, kTechnique);
        if (c.technique != 6 || c.scene == 3) break;
        out << "the combination of techniques is available for the street only\n";
    }
    c.manipulator = ask(in, out, kManipulator);
    if (c.technique == 5) {  // seed 002 asks the LiSPSM cameras across and down (its section 3.5)
        c.tilesAcross = askCount(in, out, "LiSPSM cameras across");
        c.tilesDown = askCount(in, out, "LiSPSM cameras down");
    }
    return c;
}

std::string seedCommandLine(const SeedChoices& c) {
    std::string s = "penumbra view";
    const auto add = [&](const char* flag, int v) {
        if (v) s += std::string(" ") + flag + " " + std::to_string(v);
    };
    add("-sc", c.scene);
    add("-sh", c.technique);
    add("-m", c.manipulator);
    add("-cw", c.tilesAcross);
    add("-ch", c.tilesDown);
    return s;
}

}  // namespace penumbra::app
