#pragma once
// A live, typed knob of a shadow technique: the window panel shows it as a slider, checkbox or
// combo box by its kind; the command line sets it as `--param name=value`, where a choice takes
// its label and a flag takes true/false (or on/off, 1/0); `penumbra techniques --verbose` prints
// each with its range, default and help. The technique owns the value; a Parameter points at it.
#include <string>
#include <utility>
#include <vector>

namespace penumbra::shadows {

struct Parameter {
    enum class Kind { Real, Integer, Flag, Choice };

    std::string name;
    Kind kind = Kind::Real;
    std::string help;                 // one line: what it does, in which units
    float min = 0.0f, max = 1.0f;     // Real and Integer; a Choice spans 0..labels.size()-1
    std::vector<std::string> labels;  // Choice: the name of each value
    std::string defaultText;          // the value a fresh technique has (filled by the registry)

    static Parameter real(std::string name, float& value, float min, float max, std::string help);
    static Parameter integer(std::string name, int& value, int min, int max, std::string help);
    static Parameter flag(std::string name, bool& value, std::string help);
    static Parameter choice(std::string name, int& value, std::vector<std::string> labels, std::string help);

    // The current value as text (a choice's label, "true"/"false" for a flag).
    std::string text() const;
    // The current value as a number (a choice's index, 0/1 for a flag), e.g. for JSON.
    double number() const;
    // Sets the value from text; numbers are clamped into the range. Throws std::invalid_argument
    // naming the parameter and what it accepts.
    void set(const std::string& text);
    // "0..16", "true | false", "pcf9 | poisson16 | ..." for help texts and error messages.
    std::string accepted() const;

    // Exactly one of these points at the technique's value, as `kind` says.
    float* realValue = nullptr;
    int* intValue = nullptr;
    bool* flagValue = nullptr;
};

// Parameter settings as text, by name: {"filter", "cross13"}, {"stabilize", "true"}, {"lambda", "0.5"}.
using ParameterValues = std::vector<std::pair<std::string, std::string>>;

// Sets the named parameters the list has; returns the names it does not have. Throws
// std::invalid_argument for a value a parameter does not accept.
std::vector<std::string> applyParameters(std::vector<Parameter> parameters, const ParameterValues& values);

// "technique:name=value<separator>name=value..." -> ("technique", values), each part as
// parseParameter takes it (and throws). `bench --techniques` and the tests separate by ':' (their
// list is comma-separated), `--split` by ','.
std::pair<std::string, ParameterValues> splitTechniqueParameters(const std::string& spec, char separator = ':');
// Splits "name=value"; throws std::invalid_argument on text without '='.
std::pair<std::string, std::string> parseParameter(const std::string& text);

}  // namespace penumbra::shadows
