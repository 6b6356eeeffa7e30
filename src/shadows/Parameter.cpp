#include "shadows/Parameter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace penumbra::shadows {

Parameter Parameter::real(std::string name, float& value, float min, float max, std::string help) {
    Parameter p{.name = std::move(name), .kind = Kind::Real, .help = std::move(help), .min = min, .max = max};
    p.realValue = &value;
    return p;
}

Parameter Parameter::integer(std::string name, int& value, int min, int max, std::string help) {
    Parameter p{.name = std::move(name), .kind = Kind::Integer, .help = std::move(help),
                .min = static_cast<float>(min), .max = static_cast<float>(max)};
    p.intValue = &value;
    return p;
}

Parameter Parameter::flag(std::string name, bool& value, std::string help) {
    Parameter p{.name = std::move(name), .kind = Kind::Flag, .help = std::move(help)};
    p.flagValue = &value;
    return p;
}

Parameter Parameter::choice(std::string name, int& value, std::vector<std::string> labels, std::string help) {
    Parameter p{.name = std::move(name), .kind = Kind::Choice, .help = std::move(help), .min = 0,
                .max = static_cast<float>(labels.size()) - 1, .labels = std::move(labels)};
    p.intValue = &value;
    return p;
}

static std::string formatNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

std::string Parameter::text() const {
    switch (kind) {
        case Kind::Real: return formatNumber(*realValue);
        case Kind::Integer: return std::to_string(*intValue);
        case Kind::Flag: return *flagValue ? "true" : "false";
        case Kind::Choice:
            return *intValue >= 0 && *intValue < static_cast<int>(labels.size()) ? labels[static_cast<std::size_t>(*intValue)]
                                                                                 : std::to_string(*intValue);
    }
    return "";
}

double Parameter::number() const {
    switch (kind) {
        case Kind::Real: return *realValue;
        case Kind::Flag: return *flagValue ? 1.0 : 0.0;
        default: return *intValue;
    }
}

std::string Parameter::accepted() const {
    switch (kind) {
        case Kind::Real: return formatNumber(min) + ".." + formatNumber(max);
        case Kind::Integer: return std::to_string(static_cast<int>(min)) + ".." + std::to_string(static_cast<int>(max));
        case Kind::Flag: return "true | false";
        case Kind::Choice: {
            std::string list;
            for (const auto& l : labels) list += (list.empty() ? "" : " | ") + l;
            return list;
        }
    }
    return "";
}

static bool parseNumber(const std::string& text, double& out) {
    try {
        std::size_t used = 0;
        out = std::stod(text, &used);
        return used == text.size() && std::isfinite(out);
    } catch (const std::exception&) {
        return false;
    }
}

void Parameter::set(const std::string& text) {
    const auto reject = [&] {
        throw std::invalid_argument("parameter '" + name + "': '" + text + "' is not accepted; expected " + accepted());
    };
    double v = 0;
    switch (kind) {
        case Kind::Flag:
            if (text == "true" || text == "on" || text == "1") *flagValue = true;
            else if (text == "false" || text == "off" || text == "0") *flagValue = false;
            else reject();
            return;
        case Kind::Choice:
            for (std::size_t i = 0; i < labels.size(); ++i)
                if (labels[i] == text) {
                    *intValue = static_cast<int>(i);
                    return;
                }
            // An index is accepted too (scripts written against the numbers).
            if (!parseNumber(text, v) || v != std::floor(v) || v < 0 || v > max) reject();
            *intValue = static_cast<int>(v);
            return;
        case Kind::Integer:
            if (!parseNumber(text, v)) reject();
            *intValue = static_cast<int>(std::lround(std::clamp(v, static_cast<double>(min), static_cast<double>(max))));
            return;
        case Kind::Real:
            if (!parseNumber(text, v)) reject();
            *realValue = static_cast<float>(std::clamp(v, static_cast<double>(min), static_cast<double>(max)));
            return;
    }
}

std::vector<std::string> applyParameters(std::vector<Parameter> parameters, const ParameterValues& values) {
    std::vector<std::string> unknown;
    for (const auto& [name, value] : values) {
        auto it = std::find_if(parameters.begin(), parameters.end(), [&](const Parameter& p) { return p.name == name; });
        if (it == parameters.end()) unknown.push_back(name);
        else it->set(value);
    }
    return unknown;
}

std::pair<std::string, std::string> parseParameter(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throw std::invalid_argument("--param expects name=value, got '" + text + "'");
    return {text.substr(0, eq), text.substr(eq + 1)};
}

std::pair<std::string, ParameterValues> splitTechniqueParameters(const std::string& spec, char separator) {
    const std::size_t colon = spec.find(':');
    std::pair<std::string, ParameterValues> out{spec.substr(0, colon), {}};
    if (colon == std::string::npos) return out;
    for (std::size_t start = colon + 1; start <= spec.size();) {
        const std::size_t end = std::min(spec.find(separator, start), spec.size());
        out.second.push_back(parseParameter(spec.substr(start, end - start)));
        start = end + 1;
    }
    return out;
}

}  // namespace penumbra::shadows
