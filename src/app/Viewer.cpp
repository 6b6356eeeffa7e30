// The window front-end: GLFW input -> camera controller / renderer options; ImGui panel.
#include "app/Viewer.h"

#include "app/MallocTuning.h"
#include "gl/Debug.h"
#include "platform/EglContext.h"
#include "platform/GlfwWindow.h"
#include "util/OutputFiles.h"
#include "app/RenderOptionsCli.h"
#include "app/ShaderWatcher.h"
#include "render/Offscreen.h"
#include "render/Renderer.h"
#include "render/RegionView.h"
#include "render/SplitView.h"
#include "reference/BackgroundReference.h"
#include "gl/Texture.h"
#include "scene/CameraController.h"
#include "scene/io/SceneFile.h"
#include "util/DataPaths.h"
#include "util/Log.h"
#include "util/Srgb.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <utility>
#include <cstdio>
#include <functional>
#include <glm/gtx/rotate_vector.hpp>

namespace penumbra::app {

namespace {

constexpr int kResolutionKeys[] = {256, 512, 1024, 2048, 4096};  // keys 1-5 (Plachý 2012 §3.4)

struct ViewerState {
    bool animate = true;
    bool showFps = true;
    bool showPanel = true;
    float time = 0.0f;
    int selectedLight = 0;
    bool screenshotRequested = false;
    int screenshotCount = 0;
    double frameSeconds = 0.0;  // exponentially smoothed frame time
    std::string shaderError;    // the last live reload's compile error, "" when the shaders are good
    std::vector<std::filesystem::path> dropped;  // files dropped on the window, not yet loaded
    std::string loadError;      // the last dropped file's error, "" once one loads
    float divider = 0.5f;       // split view: share of the width left of the divider
    // Reference mode (r): the ray-traced frame of the view when r was pressed, traced in the
    // background; g toggles the heat map |technique - reference|. Moving the camera, resizing or
    // pressing r again leaves it.
    std::unique_ptr<reference::BackgroundReference> reference;
    gl::Texture referenceImage, heatImage;
    bool showHeat = false;
    bool draggingDivider = false;
    bool swapSides = false;  // x: the split view's renderers change places
    bool byRegion = false;   // k: the scene's regions, each with its own technique (render/RegionView.h)
    // A technique chosen in the panel (or the split view's right side, v) is made after a frame
    // that says so: its first frame builds and compiles its shaders, 3-5 s on llvmpipe with Mesa's
    // shader cache cold, 0.25-0.35 s warm (default scene, stop 79), and the window would freeze
    // without a word. So is a new renderer's first frame (the window's, a dropped scene's): the
    // frame before it shows the notice over the cleared window, nothing of the scene drawn yet.
    struct Pending {
        std::string name;        // the technique, or the scene file opened; "" = none
        bool opening = false;    // a new renderer's first frame, not a technique's
        bool announced = false;  // its notice was drawn in a frame already on screen
        void set(std::string what, bool opens = false) { *this = {std::move(what), opens, false}; }
        bool waiting() const { return !name.empty(); }
        std::string notice() const { return (opening ? "opening " : "building ") + name + ": its first frame compiles its shaders"; }
        // The name once announced, taken; "" before.
        std::string takeAnnounced() { return announced ? std::exchange(*this, {}).name : std::string(); }
    };
    Pending pendingOpening, pendingTechnique, pendingSplit;
    double fps() const { return frameSeconds > 0 ? 1.0 / frameSeconds : 0.0; }
};

// Rotates a light: direction for directional lights, position around the scene centre otherwise.
void moveLight(scene::Light& light, float yaw, float pitch, const glm::vec3& pivot) {
    if (light.type == scene::Light::Type::Directional) {
        glm::vec3 d = glm::rotate(light.direction, yaw, glm::vec3(0, 1, 0));
        const glm::vec3 side = glm::normalize(glm::cross(d, glm::vec3(0, 1, 0)));
        const glm::vec3 pitched = glm::rotate(d, pitch, side);
        if (pitched.y < -0.05f) d = pitched;  // keep the sun above the horizon
        light.direction = glm::normalize(d);
        return;
    }
    glm::vec3 offset = glm::rotate(light.position - pivot, yaw, glm::vec3(0, 1, 0));
    light.position = pivot + offset;
    light.direction = glm::normalize(glm::rotate(light.direction, yaw, glm::vec3(0, 1, 0)));
}

// A parameter as the widget of its kind: slider, checkbox or combo box; its help as a tooltip.
void parameterWidget(const shadows::Parameter& p) {
    using Kind = shadows::Parameter::Kind;
    switch (p.kind) {
        case Kind::Real: ImGui::SliderFloat(p.name.c_str(), p.realValue, p.min, p.max); break;
        case Kind::Integer:
            ImGui::SliderInt(p.name.c_str(), p.intValue, static_cast<int>(p.min), static_cast<int>(p.max));
            break;
        case Kind::Flag: ImGui::Checkbox(p.name.c_str(), p.flagValue); break;
        case Kind::Choice:
            if (ImGui::BeginCombo(p.name.c_str(), p.text().c_str())) {
                for (std::size_t i = 0; i < p.labels.size(); ++i)
                    if (ImGui::Selectable(p.labels[i].c_str(), static_cast<int>(i) == *p.intValue)) *p.intValue = static_cast<int>(i);
                ImGui::EndCombo();
            }
            break;
    }
    if (ImGui::IsItemHovered() && !p.help.empty()) ImGui::SetTooltip("%s (default %s)", p.help.c_str(), p.defaultText.c_str());
}

// The notice drawn over the frame before a first frame that may take seconds (a chosen technique's,
// a new renderer's: ViewerState::Pending::notice). Sized here, not auto-resized: ImGui hides an
// auto-resizing window on its first frame, and this one has only one.
void drawBuildingNotice(const std::string& text) {
    const ImVec2 display = ImGui::GetIO().DisplaySize, padding = ImGui::GetStyle().WindowPadding;
    const ImVec2 textSize = ImGui::CalcTextSize(text.c_str());
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(textSize.x + 2.0f * padding.x, textSize.y + 2.0f * padding.y), ImGuiCond_Always);
    ImGui::Begin("building", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings);
    ImGui::TextUnformatted(text.c_str());
    ImGui::End();
}

// The window cleared to the scene's background, nothing of the scene drawn: the frame of a new
// renderer's notice (drawing the scene would be the very wait it announces).
void clearWindow(const scene::Scene& scene, int w, int h) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, w, h);
    const glm::vec3 background = util::linearToSrgb(scene.background);  // the window's bytes are sRGB
    glClearColor(background.r, background.g, background.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

// A technique made (`make`: chosen in the panel, or the split view's right side; nothing for a new
// renderer), then the frame, timed to its end into the log: the first frame compiles the shaders.
void makeThenDrawTimed(const std::string& technique, const std::function<void()>& make, const std::function<void()>& drawFrame) {
    const auto start = std::chrono::steady_clock::now();
    try {
        make();
    } catch (const std::exception& e) {  // nothing changed: the frame as it was
        log::error("{}", e.what());
        drawFrame();
        return;
    }
    drawFrame();
    glFinish();  // the compiles happen at the first draws; count them all
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start);
    log::info("{}: first frame {} ms (shaders built and compiled)", technique, ms.count());
}

// The panel: docked on the left, at most a third of the window wide, its sections collapsed
// except the technique's, so the scene stays visible (h hides it).
// The GPU times of what is drawn: every region's renderer together when drawing by region.
render::PassTimes shownTimes(const render::Renderer& renderer, const render::RegionView* regions, const ViewerState& state) {
    return state.byRegion && regions ? regions->lastTimes() : renderer.lastTimes();
}

void drawPanel(render::Renderer& renderer, const render::RegionView* regions, ViewerState& state, scene::CameraController& controller) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float width = std::min(display.x / 3.0f, 340.0f * ImGui::GetIO().FontGlobalScale);
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, display.y), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.75f);
    ImGui::Begin("penumbra", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 7.0f);  // labels keep 7 em on the right
    // By region: every region's renderer together (its own maps, its own passes).
    const bool byRegion = state.byRegion && regions;
    const render::PassTimes t = shownTimes(renderer, regions, state);
    const std::size_t shadowBytes = byRegion ? regions->shadowMemoryBytes() : renderer.shadowMemoryBytes();
    ImGui::Text("%.1f FPS, GPU %.1f ms", state.fps(), t.totalMs());
    ImGui::Text("shadow %.1f | opaque %.1f ms", t.shadowMs, t.opaqueMs);
    ImGui::Text("shadow memory %.1f MiB", static_cast<double>(shadowBytes) / (1024.0 * 1024.0));
    if (!state.loadError.empty()) {  // a dropped file that did not load: the old scene keeps drawing
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("could not load the dropped file (the previous scene stays):\n%s", state.loadError.c_str());
        ImGui::PopStyleColor();
    }
    if (!state.shaderError.empty()) {  // live editing: the last good programs keep drawing
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("shader error (last good shaders drawing):\n%s", state.shaderError.c_str());
        ImGui::PopStyleColor();
    }

    if (const auto& regions = renderer.scene().regions; !regions.empty()) {  // seed 002's combined technique
        ImGui::Checkbox("a technique per region (k)", &state.byRegion);
        if (state.byRegion)
            for (const scene::Region& r : regions)
                ImGui::BulletText("%s: %s%s", r.name.c_str(), r.technique.empty() ? "(scene's)" : r.technique.c_str(),
                                  r.shadowResolution > 0 ? (" " + std::to_string(r.shadowResolution)).c_str() : "");
    }
    if (ImGui::CollapsingHeader("technique", ImGuiTreeNodeFlags_DefaultOpen)) {
        const std::string current = renderer.technique().name();
        if (ImGui::BeginCombo("technique", current.c_str())) {
            for (const auto& info : shadows::techniqueRegistry())
                if (ImGui::Selectable(info.name.c_str(), info.name == current) && info.name != current)
                    state.pendingTechnique.set(info.name);  // made and drawn after this frame and its notice
            ImGui::EndCombo();
        }
        int& res = renderer.options().shadowResolution;
        ImGui::InputInt("map res (0: own)", &res, 256, 1024);
        res = std::clamp(res, 0, 8192);
        for (const auto& p : renderer.technique().parameters()) parameterWidget(p);
        ImGui::Checkbox("debug maps (o)", &renderer.options().debugOverlay);
    }
    if (ImGui::CollapsingHeader("view and animation")) {
        int transparency = static_cast<int>(renderer.options().transparency);
        if (ImGui::Combo("transparency", &transparency, "sorted-objects\0sorted-triangles\0depth-peeling\0dual-depth-peeling\0weighted\0stochastic\0"))
            renderer.options().transparency = static_cast<render::TransparencyMode>(transparency);
        if (renderer.options().transparency == render::TransparencyMode::DepthPeeling ||
            renderer.options().transparency == render::TransparencyMode::DualDepthPeeling)
            ImGui::SliderInt("peel layers", &renderer.options().peelLayers, 1, 16);
        int anisotropy = renderer.options().anisotropy;
        if (ImGui::SliderInt("anisotropy", &anisotropy, 1, 16)) renderer.setAnisotropy(anisotropy);
        ImGui::Checkbox("keep still casters' shadow maps", &renderer.options().reuseStillCasters);
        ImGui::Checkbox("hold the sun's box while it holds the view", &renderer.options().holdSunBox);
        ImGui::Checkbox("animate (space)", &state.animate);
        ImGui::SliderFloat("time", &state.time, 0.0f, 60.0f);
        int mode = static_cast<int>(controller.mode());
        if (ImGui::Combo("camera (c)", &mode, "fly\0trackball\0orbit\0")) controller.setMode(static_cast<scene::Camera::Controller>(mode));
    }
    auto& lights = renderer.scene().lights;
    if (!lights.empty() && ImGui::CollapsingHeader("lights")) {
        state.selectedLight = std::clamp(state.selectedLight, 0, static_cast<int>(lights.size()) - 1);
        if (ImGui::BeginCombo("light", lights[static_cast<std::size_t>(state.selectedLight)].name.c_str())) {
            for (std::size_t i = 0; i < lights.size(); ++i)
                if (ImGui::Selectable(lights[i].name.c_str(), static_cast<int>(i) == state.selectedLight))
                    state.selectedLight = static_cast<int>(i);
            ImGui::EndCombo();
        }
        scene::Light& l = lights[static_cast<std::size_t>(state.selectedLight)];
        ImGui::ColorEdit3("colour", &l.color.x);
        ImGui::SliderFloat("intensity", &l.intensity, 0.0f, 5.0f);
        if (l.type == scene::Light::Type::Directional) {
            if (ImGui::SliderFloat3("direction", &l.direction.x, -1.0f, 1.0f) && glm::length(l.direction) > 1e-3f)
                l.direction = glm::normalize(l.direction);
        } else {
            ImGui::DragFloat3("position", &l.position.x, 0.05f);
        }
        ImGui::Checkbox("casts shadows", &l.shadow.enabled);
        ImGui::SliderFloat("bias (texels)", &l.shadow.bias, 0.0f, 20.0f);
        ImGui::SliderFloat("slope bias", &l.shadow.slopeBias, 0.0f, 10.0f);
        ImGui::SliderFloat("normal offset", &l.shadow.normalOffset, 0.0f, 10.0f);
        ImGui::SliderFloat2("polygon offset", &l.shadow.polygonOffset.x, 0.0f, 10.0f);
    }
    if (ImGui::CollapsingHeader("keys"))
        ImGui::TextWrapped("WASD/QE move, right-drag look, arrows move the light, 1-5 map resolution, space animation, "
                           "o debug maps, c camera, v split view (drag the divider), x swap the halves, k a technique per region, r reference of this view, "
                           "g its heat map, m full screen, n FPS, "
                           "h hide panel, p screenshot, Esc quit");
    ImGui::PopItemWidth();
    ImGui::End();
}

void saveScreenshot(const ViewerOptions& opts, ViewerState& state, int w, int h) {
    char name[64];
    std::snprintf(name, sizeof name, "screenshot_%03d.png", state.screenshotCount++);
    const auto file = opts.screenshotDir / name;
    util::writePng(file, w, h, render::readFramebufferRgba8(0, w, h));
    std::printf("penumbra: saved %s\n", file.string().c_str());
}

}  // namespace

// One step of the --storm drill: the window is minimised, restored and resized to extremes,
// and the technique changes, faster than any person would do it.
static void stormDrill(GLFWwindow* win, render::Renderer& renderer, const std::vector<shadows::TechniqueInfo>& registry, int step) {
    switch (step % 6) {
        case 0: glfwIconifyWindow(win); break;
        case 1: glfwRestoreWindow(win); break;
        case 2: glfwSetWindowSize(win, 1, 1); break;
        case 3: glfwSetWindowSize(win, 8192, 8192); break;
        case 4: glfwSetWindowSize(win, 800, 600); break;
        default: renderer.setTechnique(registry[static_cast<std::size_t>(step / 6) % registry.size()].name); break;
    }
}

constexpr int kReferenceSamples = 16;  // per pixel, for area lights

// Starts tracing the reference of the frame now on screen, and freezes the animation on it.
void enterReference(ViewerState& state, const scene::Scene& scene, int w, int h) {
    state.reference = std::make_unique<reference::BackgroundReference>(scene, w, h, state.time, kReferenceSamples);
    state.animate = false;
}

void leaveReference(ViewerState& state) {
    state.reference.reset();  // waits for a tracer still running
    state.referenceImage = gl::Texture();
    state.heatImage = gl::Texture();
    state.showHeat = false;
}

gl::Texture imageTexture(const std::vector<std::uint8_t>& rgba, int w, int h) {
    gl::Texture t = gl::Texture::create2D(GL_RGBA8, w, h);
    glTextureSubImage2D(t.id(), 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    t.setFilter(GL_NEAREST, GL_NEAREST);
    return t;
}

// Reference mode over the frame: a progress bar while tracing, then the reference (or the
// heat map of the left/only technique against it) over the whole window, labelled.
void drawReference(ViewerState& state, render::Renderer& renderer) {
    reference::BackgroundReference& ref = *state.reference;
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, 8.0f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
    ImGui::Begin("reference", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize);
    if (!ref.ready()) {
        ImGui::Text("ray-tracing the reference of this frame (Embree, %d samples)", kReferenceSamples);
        ImGui::ProgressBar(static_cast<float>(ref.progress()), ImVec2(320.0f, 0.0f));
        ImGui::End();
        return;
    }
    try {
        if (state.referenceImage.id() == 0) state.referenceImage = imageTexture(ref.image(), ref.width(), ref.height());
        if (state.showHeat && state.heatImage.id() == 0)
            state.heatImage = imageTexture(ref.heatMap(renderer.technique().name()), ref.width(), ref.height());
    } catch (const std::exception& e) {
        log::error("{}", e.what());
        ImGui::End();
        leaveReference(state);
        return;
    }
    const gl::Texture& shown = state.showHeat ? state.heatImage : state.referenceImage;
    ImGui::GetBackgroundDrawList()->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(shown.id())), ImVec2(0, 0), size);
    if (state.showHeat) ImGui::Text("|%s - reference| (g: reference, r: leave)", renderer.technique().name().c_str());
    else ImGui::Text("ray-traced reference (g: heat map, r: leave)");
    ImGui::End();
}

// The technique after `name` in the registry: what `v` puts on the right of a new split view.
std::string nextTechnique(const std::string& name) {
    const auto& registry = shadows::techniqueRegistry();
    for (std::size_t i = 0; i < registry.size(); ++i)
        if (registry[i].name == name) return registry[(i + 1) % registry.size()].name;
    return registry.front().name;
}

// Each half of a split view named at the top, beside the divider.
void labelSplit(const render::Renderer& left, const render::Renderer& right, float divider) {
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const float x = divider * ImGui::GetIO().DisplaySize.x, pad = 8.0f;
    const std::string l = "< " + left.technique().name(), r = right.technique().name() + " >";
    const ImVec2 size = ImGui::CalcTextSize(l.c_str());
    for (const auto& [pos, text] : {std::pair{ImVec2(x - pad - size.x, pad), l}, std::pair{ImVec2(x + pad, pad), r}}) {
        const ImVec2 extent = ImGui::CalcTextSize(text.c_str());
        draw->AddRectFilled(ImVec2(pos.x - 3, pos.y - 2), ImVec2(pos.x + extent.x + 3, pos.y + extent.y + 2), IM_COL32(0, 0, 0, 160));
        draw->AddText(pos, IM_COL32(255, 255, 255, 255), text.c_str());
    }
}

int runViewer(const ViewerOptions& opts) {
    log::info("glibc malloc: {}", configureMalloc(opts.tunedMalloc)["mode"].get<std::string>());
    // Scene, renderer and camera controller are replaced whole when a file is dropped on the
    // window (seed 001's way of opening a scene); each frame works on the current ones.
    auto scenePtr = std::make_unique<scene::Scene>(scene::io::loadScene(opts.scene));
    platform::GlfwWindow window(opts.width, opts.height, "penumbra - " + opts.scene.filename().string(), opts.debugContext);
    if (opts.debugContext) gl::enableDebugOutput();
    log::info("window on {}", platform::glDeviceDescription());

    auto rendererPtr = std::make_unique<render::Renderer>(*scenePtr, opts.render);
    // Split view (render/SplitView.h): the right side's own renderer, null when off.
    std::unique_ptr<render::Renderer> right;
    if (!opts.split.empty()) right = std::make_unique<render::Renderer>(*scenePtr, splitSideOptions(opts.render, opts.split));
    // The scene's regions (render/RegionView.h), built when first shown, dropped when the scene changes.
    std::unique_ptr<render::RegionView> regions;
    auto controllerPtr = std::make_unique<scene::CameraController>(scenePtr->camera);
    if (opts.controller == "trackball") controllerPtr->setMode(scene::Camera::Controller::Trackball);
    if (opts.controller == "orbit") controllerPtr->setMode(scene::Camera::Controller::Orbit);
    glm::vec3 pivot = scenePtr->boundsAt(0.0f).center();

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    // Scale fonts and widgets with the display's content scale (HiDPI).
    float scaleX = 1.0f, scaleY = 1.0f;
    glfwGetWindowContentScale(window.handle(), &scaleX, &scaleY);
    ImGui::GetIO().FontGlobalScale = std::max(1.0f, scaleY);
    ImGui::GetStyle().ScaleAllSizes(std::max(1.0f, scaleY));
    ImGui_ImplGlfw_InitForOpenGL(window.handle(), true);
    ImGui_ImplOpenGL3_Init("#version 450 core");

    ViewerState state;
    state.pendingOpening.set(opts.scene.filename().string(), true);
    state.byRegion = render::drawsByRegion(opts.render, *scenePtr) && !right;
    GLFWwindow* win = window.handle();
    glfwSetWindowUserPointer(win, &state);
    glfwSetDropCallback(win, [](GLFWwindow* w, int count, const char** paths) {
        auto* s = static_cast<ViewerState*>(glfwGetWindowUserPointer(w));
        if (count > 0) s->dropped.emplace_back(paths[count - 1]);  // several at once: the last one
    });
    state.dropped = opts.drop;
    std::string scriptedChoice = opts.choose;  // chosen during the first frame's panel, as a click is
    if (opts.referenceMode) {  // as if r were pressed on the first frame
        int w = 0, h = 0;
        window.framebufferSize(w, h);
        if (w > 0 && h > 0) enterReference(state, *scenePtr, w, h);
        state.showHeat = opts.heatMap;
    }
    auto previous = std::chrono::steady_clock::now();
    double lastX = 0, lastY = 0;
    glfwGetCursorPos(win, &lastX, &lastY);
    int frame = 0;
    bool keyWasDown[GLFW_KEY_LAST + 1] = {};
    auto pressed = [&](int key) {  // edge-triggered key press
        const bool down = glfwGetKey(win, key) == GLFW_PRESS;
        const bool edge = down && !keyWasDown[key];
        keyWasDown[key] = down;
        return edge;
    };

    ShaderWatcher shaders(paths::dataRoot());
    int stormStep = 0;
    const auto& registry = shadows::techniqueRegistry();
    while (!window.shouldClose()) {
        glfwPollEvents();
        for (const auto& file : std::exchange(state.dropped, {})) {
            // Load and build everything first: a broken file changes nothing but the message.
            try {
                auto next = std::make_unique<scene::Scene>(scene::io::loadScene(file));
                const bool nextByRegion = render::drawsByRegion(opts.render, *next);
                render::RenderOptions options = rendererPtr->options();
                auto nextRenderer = std::make_unique<render::Renderer>(*next, options);
                std::unique_ptr<render::Renderer> nextRight;
                if (right) nextRight = std::make_unique<render::Renderer>(*next, right->options());
                if (state.reference) leaveReference(state);
                controllerPtr = std::make_unique<scene::CameraController>(next->camera);
                rendererPtr = std::move(nextRenderer);
                right = std::move(nextRight);
                regions.reset();
                state.byRegion = nextByRegion && !right;
                scenePtr = std::move(next);
                pivot = scenePtr->boundsAt(0.0f).center();
                state.time = 0.0f;
                state.selectedLight = 0;
                state.loadError.clear();
                state.pendingOpening.set(file.filename().string(), true);
                glfwSetWindowTitle(win, ("penumbra - " + file.filename().string()).c_str());
                log::info("loaded {}", file.string());
            } catch (const std::exception& e) {
                state.loadError = e.what();
                log::error("{}", e.what());
            }
        }
        if (std::exchange(state.swapSides, false) && right) std::swap(rendererPtr, right);  // with their parameters
        scene::Scene& scene = *scenePtr;
        render::Renderer& renderer = *rendererPtr;
        scene::CameraController& controller = *controllerPtr;
        if (opts.resizeStorm) stormDrill(win, renderer, registry, stormStep++);
        if (shaders.changed()) {  // a shader file was saved: rebuild, or keep the last good programs
            state.shaderError = renderer.reloadShaders();
            if (right && state.shaderError.empty()) state.shaderError = right->reloadShaders();
            if (state.shaderError.empty()) regions.reset();  // rebuilt from the new files when next drawn
            if (state.shaderError.empty()) log::info("shaders reloaded");
            else log::error("{}", state.shaderError);
        }
        int w = 0, h = 0;
        window.framebufferSize(w, h);
        if (w == 0 || h == 0) {  // minimised: wait instead of spinning, draw nothing
            glfwWaitEventsTimeout(0.1);
            continue;
        }
        const auto now = std::chrono::steady_clock::now();
        const float dt = std::min(std::chrono::duration<float>(now - previous).count(), 0.25f);
        previous = now;
        state.frameSeconds = state.frameSeconds > 0 ? state.frameSeconds * 0.9 + dt * 0.1 : dt;
        if (state.animate) state.time += dt;

        const ImGuiIO& io = ImGui::GetIO();
        if (!io.WantCaptureKeyboard) {
            if (pressed(GLFW_KEY_ESCAPE)) glfwSetWindowShouldClose(win, GLFW_TRUE);
            if (pressed(GLFW_KEY_M)) window.toggleFullscreen();
            if (pressed(GLFW_KEY_N)) state.showFps = !state.showFps;
            if (pressed(GLFW_KEY_H)) state.showPanel = !state.showPanel;
            if (pressed(GLFW_KEY_SPACE)) state.animate = !state.animate;
            if (pressed(GLFW_KEY_O)) renderer.options().debugOverlay = !renderer.options().debugOverlay;
            if (pressed(GLFW_KEY_P) || pressed(GLFW_KEY_F12)) state.screenshotRequested = true;
            if (pressed(GLFW_KEY_R)) {
                if (state.reference) leaveReference(state);
                else enterReference(state, scene, w, h);
            }
            if (pressed(GLFW_KEY_G) && state.reference) state.showHeat = !state.showHeat;
            if (pressed(GLFW_KEY_V)) {  // split view on (the next technique on the right, after its notice) / off
                if (right) right.reset();
                else state.pendingSplit.set(nextTechnique(renderer.technique().name()));
            }
            if (pressed(GLFW_KEY_K) && !scene.regions.empty()) state.byRegion = !state.byRegion;
            if (pressed(GLFW_KEY_X) && right) state.swapSides = true;  // done before the next frame binds them
            if (pressed(GLFW_KEY_C)) controller.setMode(static_cast<scene::Camera::Controller>((static_cast<int>(controller.mode()) + 1) % 3));
            for (int k = 0; k < 5; ++k)
                if (pressed(GLFW_KEY_1 + k)) renderer.options().shadowResolution = kResolutionKeys[k];
            if (!scene.lights.empty()) {
                const float yaw = (glfwGetKey(win, GLFW_KEY_RIGHT) - glfwGetKey(win, GLFW_KEY_LEFT)) * dt;
                const float pitch = (glfwGetKey(win, GLFW_KEY_UP) - glfwGetKey(win, GLFW_KEY_DOWN)) * dt;
                if (yaw != 0 || pitch != 0)
                    moveLight(scene.lights[static_cast<std::size_t>(std::clamp(state.selectedLight, 0, int(scene.lights.size()) - 1))], yaw, pitch, pivot);
            }
        }
        scene::ControllerInput input;
        input.dt = dt;
        input.viewport = {static_cast<float>(w), static_cast<float>(h)};
        double x = 0, y = 0;
        glfwGetCursorPos(win, &x, &y);
        // A left press within a few pixels of the divider drags it instead of the camera.
        const bool leftDown = glfwGetMouseButton(win, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        int winW = 0, winH = 0;
        glfwGetWindowSize(win, &winW, &winH);
        if (!right || !leftDown) state.draggingDivider = false;
        else if (!io.WantCaptureMouse && !state.draggingDivider && std::abs(x - state.divider * winW) < 6.0) state.draggingDivider = true;
        if (state.draggingDivider && winW > 0) state.divider = std::clamp(static_cast<float>(x / winW), 0.0f, 1.0f);
        const bool dragging = !io.WantCaptureMouse && !state.draggingDivider &&
                              (glfwGetMouseButton(win, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS || leftDown);
        if (dragging) input.dragPixels = {static_cast<float>(x - lastX), static_cast<float>(y - lastY)};
        lastX = x;
        lastY = y;
        if (!io.WantCaptureKeyboard) {
            input.move = {static_cast<float>(glfwGetKey(win, GLFW_KEY_D) - glfwGetKey(win, GLFW_KEY_A)),
                          static_cast<float>(glfwGetKey(win, GLFW_KEY_E) - glfwGetKey(win, GLFW_KEY_Q)),
                          static_cast<float>(glfwGetKey(win, GLFW_KEY_W) - glfwGetKey(win, GLFW_KEY_S))};
            input.fast = glfwGetKey(win, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS;
        }
        input.scroll = io.WantCaptureMouse ? 0.0f : io.MouseWheel;
        if (state.reference && (input.dragPixels != glm::vec2(0.0f) || input.move != glm::vec3(0.0f) || input.scroll != 0.0f ||
                                w != state.reference->width() || h != state.reference->height()))
            leaveReference(state);  // the view moved away from the frozen frame
        controller.update(input);

        if (state.byRegion && !right && !regions) {
            try {  // the regions' renderers use the window's options with the scene's techniques
                render::RenderOptions base = renderer.options();
                base.technique.clear();
                regions = std::make_unique<render::RegionView>(scene, base);
            } catch (const std::exception& e) {  // a region naming an unknown technique: say so, draw one technique
                state.loadError = e.what();
                state.byRegion = false;
                log::error("{}", e.what());
            }
        }
        const auto drawFrame = [&] {
            if (right) render::renderSplit(renderer, *right, state.divider, state.time, scene.camera, w, h, 0);
            else if (state.byRegion && regions) regions->render(state.time, scene.camera, w, h, 0);
            else renderer.render(state.time, scene.camera, w, h, 0);
        };
        try {
            if (const std::string name = state.pendingTechnique.takeAnnounced(); !name.empty()) {
                makeThenDrawTimed(name, [&] {
                    renderer.setTechnique(name);
                    state.byRegion = false;  // a technique chosen in the panel covers the whole scene
                }, drawFrame);
            } else if (const std::string side = state.pendingSplit.takeAnnounced(); !side.empty()) {
                makeThenDrawTimed(side, [&] {
                    right = std::make_unique<render::Renderer>(scene, splitSideOptions(renderer.options(), side));
                    right->holdSunBoxOf(renderer);  // both sides' maps look at the same box
                }, drawFrame);
            } else if (const std::string opened = state.pendingOpening.takeAnnounced(); !opened.empty()) {
                makeThenDrawTimed(opened, [] {}, drawFrame);
            } else if (state.pendingOpening.waiting()) {
                clearWindow(scene, w, h);
            } else {
                drawFrame();
            }
        } catch (const std::exception& e) {
            log::error("{}", e.what());
            return 1;
        }
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        if (right && !state.reference) labelSplit(renderer, *right, state.divider);  // the reference covers both halves
        if (state.reference) drawReference(state, renderer);
        if (state.showPanel) drawPanel(renderer, regions.get(), state, controller);
        else if (state.showFps) {
            ImGui::SetNextWindowPos(ImVec2(8, 8));
            ImGui::Begin("fps", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize);
            ImGui::Text("%.1f FPS  %.2f ms GPU", state.fps(), shownTimes(renderer, regions.get(), state).totalMs());
            ImGui::End();
        }
        if (!scriptedChoice.empty()) state.pendingTechnique.set(std::exchange(scriptedChoice, {}));
        // A technique chosen before a new renderer's notice was shown replaces it: the chosen
        // one's build is the wait (the renderer's own technique is never compiled).
        if (state.pendingTechnique.waiting() && !state.pendingOpening.announced) state.pendingOpening = {};
        // One notice a frame (they would share its window); a second waits for the next frame.
        for (ViewerState::Pending* pending : {&state.pendingOpening, &state.pendingTechnique, &state.pendingSplit})
            if (pending->waiting() && !pending->announced) {
                log::info("{}", pending->notice());
                drawBuildingNotice(pending->notice());
                pending->announced = true;
                break;
            }
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        // Scripted runs (--exit-after) leave a screenshot of their last frame as proof.
        const bool referencePending = state.reference && !state.referenceImage.id();
        const bool lastFrame = opts.exitAfterFrames > 0 && ++frame >= opts.exitAfterFrames && !referencePending;
        if (state.screenshotRequested || lastFrame) {
            saveScreenshot(opts, state, w, h);  // before the swap: the back buffer is still ours
            state.screenshotRequested = false;
        }
        window.swapBuffers();
        if (lastFrame) break;
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    return 0;
}

}  // namespace penumbra::app
