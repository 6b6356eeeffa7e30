// The seam between the renderer and the shadow techniques, without GL: typed parameters, the
// per-frame slot and sun policy, and the README's technique table against the registry.
#include "gpu/ShaderContract.h"
#include "shadows/Parameter.h"
#include "shadows/ShadowSlots.h"
#include "shadows/ShadowTechnique.h"

#include <fstream>
#include <gtest/gtest.h>
#include <regex>
#include <set>
#include <sstream>

namespace penumbra::shadows {
namespace {

TEST(Parameter, EachKindParsesItsOwnTextAndRejectsOthersByName) {
    float radius = 1.5f;
    int taps = 16, filter = 4;
    bool stabilize = true;
    std::vector<Parameter> list{Parameter::real("radius", radius, 0.0f, 16.0f, "r"),
                                Parameter::integer("taps", taps, 4, 32, "n"),
                                Parameter::flag("stabilize", stabilize, "s"),
                                Parameter::choice("filter", filter, {"pcf9", "poisson16", "cross13"}, "f")};
    const auto unknown = applyParameters(list, {{"radius", "40"}, {"taps", "7.6"}, {"stabilize", "off"}, {"filter", "poisson16"}, {"nope", "1"}});
    EXPECT_EQ(radius, 16.0f) << "clamped into the range";
    EXPECT_EQ(taps, 8) << "rounded";
    EXPECT_FALSE(stabilize);
    EXPECT_EQ(filter, 1);
    ASSERT_EQ(unknown, std::vector<std::string>{"nope"});
    EXPECT_EQ(list[3].text(), "poisson16");
    EXPECT_EQ(list[2].text(), "false");
    applyParameters(list, {{"filter", "2"}, {"stabilize", "1"}});  // indices and 0/1 still work
    EXPECT_EQ(filter, 2);
    EXPECT_TRUE(stabilize);
    try {
        applyParameters(list, {{"filter", "gaussian"}});
        FAIL() << "an unknown label must be rejected";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("pcf9 | poisson16 | cross13"), std::string::npos) << e.what();
    }
    EXPECT_THROW(applyParameters(list, {{"stabilize", "maybe"}}), std::invalid_argument);
    EXPECT_THROW(applyParameters(list, {{"radius", "wide"}}), std::invalid_argument);
    EXPECT_THROW(applyParameters(list, {{"filter", "7"}}), std::invalid_argument);
    EXPECT_THROW(parseParameter("radius"), std::invalid_argument);
    EXPECT_EQ(parseParameter("filter=cross13"), (std::pair<std::string, std::string>{"filter", "cross13"}));
}

scene::Light light(scene::Light::Type type, bool shadowed = true) {
    scene::Light l;
    l.type = type;
    l.shadow.enabled = shadowed;
    return l;
}

TEST(ShadowSlots, FirstComeFirstServedUpToTheContractLimits) {
    using T = scene::Light::Type;
    std::vector<scene::Light> lights{light(T::Spot), light(T::Directional, false), light(T::Point), light(T::Directional)};
    for (int i = 0; i < gpu::kMaxShadow2D; ++i) lights.push_back(light(T::Spot));
    for (int i = 0; i < gpu::kMaxShadowCube; ++i) lights.push_back(light(T::Point));
    const ShadowSlots s = ShadowSlots::assign(lights);
    ASSERT_EQ(s.size(), lights.size());
    EXPECT_EQ(s.slot[0], 0);
    EXPECT_EQ(s.slot[1], -1) << "no shadow asked";
    EXPECT_EQ(s.slot[2], 0) << "cube slots count apart";
    EXPECT_EQ(s.slot[3], 1);
    EXPECT_EQ(s.sun, 3) << "the first *shadowed* sun";
    EXPECT_EQ(s.slot[4], 2);
    EXPECT_EQ(s.slot[5], 3);
    EXPECT_EQ(s.slot[6], -1) << "past kMaxShadow2D";
    EXPECT_EQ(s.slot[8], 1);
    EXPECT_EQ(s.slot[9], -1) << "past kMaxShadowCube";
    EXPECT_EQ(s.depthUnit(3), gpu::kUnitShadow2D + 1);
    EXPECT_EQ(s.rawUnit(2), gpu::kUnitRawCube);
    EXPECT_EQ(s.tintUnit(8), gpu::kUnitTintCube + 1);
}

// Every registered technique has a row in the README's technique table and every name there is
// registered: adding a technique means adding its row.
TEST(Registry, TheReadmeTableNamesExactlyTheRegisteredTechniques) {
    std::ifstream in(std::string(PENUMBRA_SOURCE_DIR) + "/README.md");
    ASSERT_TRUE(in) << "README.md not found";
    std::set<std::string> documented;
    bool inTable = false;
    const std::regex name("`([a-z0-9-]+)`");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("## ", 0) == 0) inTable = line.find("Shadow techniques") != std::string::npos;
        if (!inTable || line.rfind("| `", 0) != 0) continue;
        const std::string firstCell = line.substr(1, line.find('|', 1) - 1);
        for (std::sregex_iterator it(firstCell.begin(), firstCell.end(), name), end; it != end; ++it) documented.insert((*it)[1]);
    }
    std::set<std::string> registered;
    for (const auto& info : techniqueRegistry()) registered.insert(info.name);
    for (const auto& n : registered) EXPECT_TRUE(documented.count(n)) << "README.md's technique table has no row for `" << n << "`";
    for (const auto& n : documented) EXPECT_TRUE(registered.count(n)) << "README.md documents `" << n << "`, which is not registered";
}

}  // namespace
}  // namespace penumbra::shadows
