#include "view/query_tokens.h"

#include <algorithm>
#include <utility>

namespace clr {
namespace {

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

std::string percent_decoded(const std::string& text) {
    std::string decoded;
    decoded.reserve(text.size());
    for (std::size_t k = 0; k < text.size(); ++k) {
        const int high = text[k] == '%' && k + 2 < text.size() ? hex_digit(text[k + 1]) : -1;
        const int low = high >= 0 ? hex_digit(text[k + 2]) : -1;
        if (low >= 0) {
            decoded += static_cast<char>(high * 16 + low);
            k += 2;
        } else {
            decoded += text[k] == '+' ? ' ' : text[k];
        }
    }
    return decoded;
}

}  // namespace

std::vector<QueryPair> query_pairs_as_sent(const std::string& target) {
    std::vector<QueryPair> pairs;
    const std::size_t query_at = target.find('?');
    if (query_at == std::string::npos) return pairs;
    const std::string query = target.substr(query_at + 1);
    for (std::size_t start = 0; start < query.size();) {
        const std::size_t end = std::min(query.find('&', start), query.size());
        const std::string pair = query.substr(start, end - start);
        start = end + 1;
        if (pair.empty()) continue;
        const std::size_t equals = pair.find('=');
        QueryPair read;
        read.name = percent_decoded(pair.substr(0, equals));
        if (equals != std::string::npos) {
            const std::string value = pair.substr(equals + 1);
            read.value = percent_decoded(value);
            read.equals_in_value = value.find('=') != std::string::npos;
        }
        pairs.push_back(std::move(read));
    }
    return pairs;
}

std::vector<std::string> query_tokens_as_sent(const std::string& target) {
    std::vector<std::string> tokens;
    for (const QueryPair& pair : query_pairs_as_sent(target))
        if (pair.name == "token") tokens.push_back(pair.value);
    return tokens;
}

}  // namespace clr
