#include "view/query_tokens.h"

#include <httplib.h>

namespace clr {

std::vector<std::string> query_tokens_as_sent(const std::string& target) {
    std::vector<std::string> tokens;
    const std::size_t query_at = target.find('?');
    if (query_at == std::string::npos) return tokens;
    const std::string query = target.substr(query_at + 1);
    for (std::size_t start = 0; start <= query.size();) {
        const std::size_t end = std::min(query.find('&', start), query.size());
        const std::string pair = query.substr(start, end - start);
        const std::size_t equals = pair.find('=');
        const bool names_token = httplib::detail::decode_url(pair.substr(0, equals), true) == "token";
        if (names_token && equals == std::string::npos) tokens.emplace_back();
        if (names_token && equals != std::string::npos)
            tokens.push_back(httplib::detail::decode_url(pair.substr(equals + 1), true));
        start = end + 1;
    }
    return tokens;
}

}  // namespace clr
