#pragma once
// The command-line options every subcommand that renders shares, registered by one helper so
// that `view`, `render`, `compare` and `bench` spell and check them alike. They fill a
// render::RenderOptions directly.
#include "render/Renderer.h"

#include <CLI/CLI.hpp>
#include <filesystem>

namespace penumbra::app {

struct RenderCli {
    bool technique = true;     // --technique NAME
    bool shadowResolution = true;  // --shadow-res N
    bool overlay = true;       // --overlay
    bool transparency = true;  // --transparency MODE, --peel-layers N
};

// Registers --technique, --shadow-res, --param (repeatable; name=value, a choice by its label,
// a flag by true/false), --overlay, --transparency and --peel-layers, as `which` asks.
void addRenderOptions(CLI::App& command, render::RenderOptions& options, RenderCli which = {});
// The options of a split view's right side: `left`'s, with the technique and parameters of
// `spec` = "TECHNIQUE[:name=value,...]" (e.g. "pcf-poisson16", "cssm2:filter=box64"). Throws
// std::invalid_argument naming the known techniques or the malformed parameter.
render::RenderOptions splitSideOptions(const render::RenderOptions& left, const std::string& spec);

// CLI11's check of an option that names a technique: "" or the error naming the known ones.
std::string checkTechniqueName(const std::string& name);

// The positional scene and --size WxH.
void addSceneAndSize(CLI::App& command, std::filesystem::path& scene, int& width, int& height, const char* defaultSize);
// --size WxH alone.
void addSize(CLI::App& command, int& width, int& height, const char* defaultSize);
// --egl-platform auto | surfaceless | device.
void addEglPlatform(CLI::App& command, std::string& platform);

}  // namespace penumbra::app
