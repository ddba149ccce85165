#include "core/message_lines.h"

#include <atomic>
#include <nlohmann/json.hpp>

namespace clr {
namespace {

std::atomic<bool> json_lines{false};

}  // namespace

void set_json_messages(bool json) { json_lines = json; }

bool json_messages() { return json_lines; }

std::string message_line(const std::string& level, const std::string& text, int exit_code) {
    if (!json_lines) return "clrender: " + (level == "info" ? "" : level + ": ") + text + "\n";
    nlohmann::json line = {{"level", level}, {"message", text}};
    if (exit_code != 0) line["exit_code"] = exit_code;
    return line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace clr
