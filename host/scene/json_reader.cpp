#include "scene/json_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string_view>
#include <utility>

#include "core/edit_distance.h"
#include "core/errors.h"
#include "core/printable_text.h"
#include "scene/text_encoding.h"

namespace clr {


// Messages quote the file: keys in locations (JSON escapes such as "\u001b" put any
// character in a key), values, and the text around a syntax error. Each is shortened, then
// escaped (core/printable_text.h), so that a file can neither break the line nor make it endless.
// The file's own name comes from the command line and may hold a newline too.
void Diagnostics::fail(const std::string& location, const std::string& detail) const {
    throw SceneError(printable(file), printable(shortened(location, kLongestLocation)),
                     printable(shortened(detail + origin_of(location), kLongestDetail)));
}

std::string Diagnostics::origin_of(const std::string& location) const {
    // The last -D that set this value, or a value that holds it, set what is read now.
    for (auto set = overridden.rbegin(); set != overridden.rend(); ++set) {
        const std::string& pointer = set->first;
        const bool inside = location.compare(0, pointer.size(), pointer) == 0 &&
                            (location.size() == pointer.size() || location[pointer.size()] == '/');
        if (inside) return " (set on the command line: -D " + set->second + ")";
    }
    return "";
}

void Diagnostics::warn(const std::string& location, const std::string& message) const {
    if (!warnings) return;
    if (warnings->size() >= kMostWarnings) {
        ++unshown_warnings;
        return;
    }
    const std::string text = printable(shortened(message + origin_of(location), kLongestDetail));
    warnings->push_back(location.empty() ? text : printable(shortened(location, kLongestLocation)) + ": " + text);
}

void Diagnostics::summarise_warnings() const {
    if (!warnings || unshown_warnings == 0) return;
    warnings->push_back(std::to_string(unshown_warnings) + " more warnings not shown (only the first " +
                        std::to_string(kMostWarnings) + " are)");
    unshown_warnings = 0;
}

std::string lowercase_ascii(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

std::string json_pointer_token(const std::string& key) {
    std::string token;
    for (char c : key) {
        if (c == '~') token += "~0";
        else if (c == '/') token += "~1";
        else token += c;
    }
    return token;
}

namespace {

// Builds the document from the parser's events as nlohmann's own builder does, and also
// tracks where it is, for two things nlohmann does not offer: a warning naming a repeated
// key, and the position of a number overflow (nlohmann reports that one without it).
class LocatingDomBuilder : public nlohmann::json_sax<Json> {
public:
    struct Failure {
        std::size_t position = 0;  // bytes read when the parser stopped
        std::string last_token;
        int id = 0;  // nlohmann's exception id: 101.. syntax, 406 number overflow
        std::string message;
        std::string location;  // JSON pointer of the value being read
    };

    // `base`: the JSON pointer of the parsed value in the scene ("" for a whole file).
    LocatingDomBuilder(Json& root, const Diagnostics& diagnostics, std::string base = "")
        : root_(root), diagnostics_(diagnostics), base_(std::move(base)) {}

    bool null() override { return add(nullptr); }
    bool boolean(bool value) override { return add(value); }
    bool number_integer(number_integer_t value) override { return add(value); }
    bool number_unsigned(number_unsigned_t value) override { return add(value); }
    bool number_float(number_float_t value, const string_t&) override { return add(value); }
    bool string(string_t& value) override { return add(value); }
    bool binary(binary_t&) override { return false; }  // cannot occur in JSON text

    bool start_object(std::size_t) override { return open(Json::object()); }
    bool start_array(std::size_t) override { return open(Json::array()); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool key(string_t& name) override {
        Frame& object = frames_.back();
        object.key = name;
        if (!object.seen_keys.insert(name).second) note_duplicate_key();
        return true;
    }

    // One warning for the repeats beyond the first few, once the whole text is read.
    void summarise_duplicate_keys() const {
        if (duplicate_keys_ <= kMostDuplicateKeyWarnings) return;
        diagnostics_.warn("", std::to_string(duplicate_keys_ - kMostDuplicateKeyWarnings) +
                                  " more duplicate keys (the last value of each is used)");
    }

    bool parse_error(std::size_t position, const std::string& last_token, const Json::exception& error) override {
        failure_ = Failure{position, last_token, error.id, error.what(), location_of_next_value()};
        return false;
    }

    const std::optional<Failure>& failure() const { return failure_; }

private:
    // An open object or array. Elements are only ever added to the innermost one, so a
    // pointer to it stays valid while it is open.
    struct Frame {
        Json* container;
        std::string key;  // objects: the key whose value comes next
        std::set<std::string> seen_keys;
    };

    Json& place(Json value) {
        if (frames_.empty()) return root_ = std::move(value);
        Frame& parent = frames_.back();
        if (parent.container->is_array()) {
            parent.container->push_back(std::move(value));
            return parent.container->back();
        }
        return (*parent.container)[parent.key] = std::move(value);
    }
    bool add(Json value) {
        place(std::move(value));
        return true;
    }
    bool open(Json container) {
        frames_.push_back({&place(std::move(container)), {}, {}});
        return true;
    }
    bool close() {
        frames_.pop_back();
        return true;
    }

    // A location is as long as the nesting is deep, so a warning for every repeated key of a
    // deeply nested object would cost the depth times the repeats: gigabytes from a file of a
    // few hundred kilobytes. The first few are named; the rest are only counted.
    static constexpr std::size_t kMostDuplicateKeyWarnings = 10;

    void note_duplicate_key() {
        if (++duplicate_keys_ <= kMostDuplicateKeyWarnings)
            diagnostics_.warn(current_location(), "duplicate key (the last value is used)");
    }

    // Where the value the parser reads next goes: in an array, after its last element.
    std::string location_of_next_value() const {
        if (frames_.empty()) return base_;
        const Frame& innermost = frames_.back();
        if (!innermost.container->is_array()) return current_location();
        std::string location = base_;
        for (std::size_t i = 0; i + 1 < frames_.size(); ++i) location += step_into(frames_[i]);
        return location + "/" + std::to_string(innermost.container->size());
    }

    static std::string step_into(const Frame& frame) {
        // In an array, the element being read is always the last one.
        return "/" + (frame.container->is_array() ? std::to_string(frame.container->size() - 1)
                                                  : json_pointer_token(frame.key));
    }

    std::string current_location() const {
        std::string location = base_;
        for (const Frame& frame : frames_) location += step_into(frame);
        return location;
    }

    Json& root_;
    const Diagnostics& diagnostics_;
    std::string base_;
    std::vector<Frame> frames_;
    std::optional<Failure> failure_;
    std::size_t duplicate_keys_ = 0;
};

// "line L, column C" of the byte at `offset`. Columns count characters, not bytes, as
// editors do: UTF-8 continuation bytes (10xxxxxx) do not start a new column.
std::string line_and_column(std::string_view text, std::size_t offset) {
    offset = std::min(offset, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < offset; ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (byte == '\n') {
            ++line;
            column = 1;
        } else if ((byte & 0xC0) != 0x80) {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// nlohmann's message without its "[json.exception...] parse error at line L, column C: "
// prefix, since we give the position ourselves.
std::string syntax_reason(const std::string& message) {
    const std::size_t column = message.find(", column ");
    const std::size_t colon = column == std::string::npos ? column : message.find(": ", column);
    return colon == std::string::npos ? message : message.substr(colon + 2);
}

// JavaScript allows a comma before a closing bracket; JSON does not. It is the commonest
// mistake in hand-edited scene files, so say so.
bool is_trailing_comma(std::string_view text, std::size_t offset) {
    if (offset == 0 || offset >= text.size() || (text[offset] != '}' && text[offset] != ']')) return false;
    const std::size_t before = text.find_last_not_of(" \t\r\n", offset - 1);
    return before != std::string_view::npos && text[before] == ',';
}

// The column of the byte at `offset` in one line of text.
std::string column_of(std::string_view text, std::size_t offset) {
    const std::string position = line_and_column(text, offset);
    return position.substr(position.find("column"));
}

[[noreturn]] void fail_syntax(std::string_view text, const LocatingDomBuilder::Failure& failure,
                              const Diagnostics& diagnostics) {
    constexpr int kNumberOverflow = 406;
    if (failure.id == kNumberOverflow) {
        // Point at the number's first character rather than just past it.
        const std::size_t start = failure.position - std::min(failure.position, failure.last_token.size());
        diagnostics.fail("", line_and_column(text, start) + ": number " + failure.last_token +
                                 " is too large (numbers must be finite)");
    }
    // `position` counts the bytes read, the offending one included.
    const std::size_t offset = failure.position == 0 ? 0 : failure.position - 1;
    std::string detail = line_and_column(text, offset) + ": " + syntax_reason(failure.message);
    if (is_trailing_comma(text, offset)) detail += " (JSON allows no comma before '}' or ']')";
    diagnostics.fail("", detail);
}

}  // namespace

Json parse_json_text(const std::string& text, const Diagnostics& diagnostics) {
    if (const auto encoding = wide_unicode_encoding(text))
        diagnostics.fail("", "the file is " + *encoding + " text; save it as UTF-8 (clrender reads only UTF-8)");
    std::string_view body = text;
    constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
    if (body.substr(0, kUtf8Bom.size()) == kUtf8Bom) body.remove_prefix(kUtf8Bom.size());
    if (body.find_first_not_of(" \t\r\n") == std::string_view::npos)
        diagnostics.fail("", "the file is empty; a scene is one JSON object { ... }");

    Json root;
    LocatingDomBuilder builder(root, diagnostics);
    const bool parsed = Json::sax_parse(body.begin(), body.end(), &builder, Json::input_format_t::json,
                                        /*strict=*/true, /*ignore_comments=*/true);
    if (!parsed) {
        if (builder.failure()) fail_syntax(body, *builder.failure(), diagnostics);
        diagnostics.fail("", "the file is not valid JSON");
    }
    builder.summarise_duplicate_keys();
    return root;
}

JsonArgument parse_json_argument(const std::string& text, const std::string& base, const Diagnostics& diagnostics) {
    Json value;
    LocatingDomBuilder builder(value, diagnostics, base);
    JsonArgument argument;
    if (Json::sax_parse(text.begin(), text.end(), &builder, Json::input_format_t::json, /*strict=*/true,
                        /*ignore_comments=*/false)) {
        builder.summarise_duplicate_keys();
        argument.value = std::move(value);
        return argument;
    }
    argument.problem_location = base;
    argument.problem = "not JSON";
    if (const auto& failure = builder.failure()) {
        constexpr int kNumberOverflow = 406;
        argument.problem_location = failure->location;
        argument.out_of_range = failure->id == kNumberOverflow;
        if (argument.out_of_range) {
            const std::size_t start = failure->position - std::min(failure->position, failure->last_token.size());
            argument.problem = column_of(text, start) + ": number " + failure->last_token +
                               " is out of range (numbers must be finite, at most about 1.8e308 in size)";
        } else {
            const std::size_t offset = failure->position == 0 ? 0 : failure->position - 1;
            argument.problem = column_of(text, offset) + ": " + syntax_reason(failure->message);
        }
    }
    return argument;
}

// ---------------------------------------------------------------------------------------
// Node

Node::Node(const Json& value, std::string location, std::string label, const Diagnostics& diagnostics)
    : value_(&value), location_(std::move(location)), label_(std::move(label)), diagnostics_(&diagnostics) {}

Node Node::member(const std::string& key) const {
    return Node(value_->at(key), location_ + "/" + json_pointer_token(key), key, *diagnostics_);
}

std::vector<Node> Node::elements() const {
    if (!value_->is_array()) fail_type("an array [ ... ]");
    std::vector<Node> elements;
    for (std::size_t i = 0; i < value_->size(); ++i) {
        const std::string index = std::to_string(i);
        elements.emplace_back((*value_)[i], location_ + "/" + index, label_ + "[" + index + "]", *diagnostics_);
    }
    return elements;
}

double Node::number() const {
    if (!value_->is_number()) fail_type("a number");
    const double value = value_->get<double>();
    if (!std::isfinite(value)) fail(label_ + " must be a finite number");
    return value;
}

long long Node::integer(long long min, long long max) const {
    const double value = number();
    // Compared as doubles first, so that a huge value cannot overflow the conversion.
    if (value != std::floor(value) || value < static_cast<double>(min) || value > static_cast<double>(max)) {
        fail(label_ + " must be a whole number from " + std::to_string(min) + " to " + std::to_string(max) +
             " (got " + shown() + ")");
    }
    return static_cast<long long>(value);
}

bool Node::flag() const {
    if (value_->is_boolean()) return value_->get<bool>();
    if (value_->is_number()) {
        const double value = value_->get<double>();
        if (value == 0 || value == 1) return value == 1;
    }
    fail(label_ + " must be 0, 1, false or true (got " + shown() + ")");
}

std::string Node::string() const {
    if (!value_->is_string()) fail_type("a string");
    return value_->get<std::string>();
}

Vec3 Node::vec3(const char* shape) const {
    const std::string expected = std::string("an array ") + shape + " of 3 numbers";
    if (!value_->is_array()) fail_type(expected);
    if (value_->size() != 3) fail(label_ + " must be " + expected + ", got " + shown());
    const std::vector<Node> parts = elements();
    return {parts[0].number(), parts[1].number(), parts[2].number()};
}

std::string Node::shown() const {
    constexpr std::size_t kLongestShownString = 40;
    const Json& value = *value_;
    if (value.is_array()) {
        const std::size_t n = value.size();
        return n == 0 ? "an empty array" : "an array of " + std::to_string(n) + (n == 1 ? " value" : " values");
    }
    if (value.is_object()) return "an object";
    if (value.is_string() && value.get_ref<const std::string&>().size() > kLongestShownString) return "a long string";
    return value.dump();  // numbers as nlohmann writes them (shortest round trip), quoted strings
}

void Node::fail_type(const std::string& expected) const {
    fail(label_ + " must be " + expected + ", got " + shown());
}

// ---------------------------------------------------------------------------------------
// ObjectReader

ObjectReader::ObjectReader(const Node& node, std::string what) : node_(node), what_(std::move(what)) {
    if (!node_.json().is_object()) node_.fail(node_.label() + " must be a JSON object { ... }, got " + node_.shown());
}

bool ObjectReader::has(const std::string& key) {
    known_keys_.insert(key);
    return node_.json().contains(key);
}

std::optional<Node> ObjectReader::optional(const std::string& key) {
    if (!has(key)) return std::nullopt;
    return node_.member(key);
}

Node ObjectReader::required(const std::string& key, const std::string& hint) {
    if (!has(key)) node_.fail(what_ + " is missing required key '" + key + "'" + hint + mistake_note(key));
    return node_.member(key);
}

void ObjectReader::note_ignored(const std::string& key, const std::string& message) {
    if (has(key)) node_.member(key).warn(message);
}

void ObjectReader::warn_about_unknown_keys() const {
    for (const auto& member : node_.json().items()) {
        if (known_keys_.count(member.key())) continue;
        node_.diagnostics().warn(node_.location() + "/" + json_pointer_token(member.key()),
                                 "unknown key (ignored)" + suggestion_for(member.key()));
    }
}

std::string ObjectReader::suggestion_for(const std::string& unknown_key) const {
    if (const auto hint = hints_.find(lowercase_ascii(unknown_key)); hint != hints_.end()) return "; " + hint->second.text;
    const std::string best = closest_spelling(unknown_key, {known_keys_.begin(), known_keys_.end()});
    return best.empty() ? "" : "; did you mean '" + best + "'?";
}

void ObjectReader::hint(const std::vector<std::string>& likely_mistakes, const std::string& right_key,
                        const std::string& hint) {
    for (const std::string& key : likely_mistakes) hints_[lowercase_ascii(key)] = {right_key, hint};
}

std::string ObjectReader::mistake_note(const std::string& right_key) const {
    if (hints_.empty()) return "";
    for (const auto& member : node_.json().items()) {
        const auto hint = hints_.find(lowercase_ascii(member.key()));
        if (hint != hints_.end() && hint->second.right_key == right_key && !known_keys_.count(member.key()))
            return " (it has '" + member.key() + "': " + hint->second.text + ")";
    }
    return "";
}

}  // namespace clr
