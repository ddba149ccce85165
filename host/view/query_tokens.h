// The token= values of a request's query, read from the request's target as sent. cpp-httplib's
// own parse of the query (Request::params) drops a name=value pair given a second time and keeps
// only what follows a value's last '=', so that "?token=T&token=T" and "?token=zzz=T" would both
// count as the one right token, where the rule is exactly one token, given whole.
#pragma once

#include <string>
#include <vector>

namespace clr {

// Every token= of the query of `target` ("/path?a=1&token=T"), in order, each value as it
// stands after the first '=' (percent-decoded, '+' a space, as cpp-httplib decodes); a name
// matches however it is percent-encoded.
std::vector<std::string> query_tokens_as_sent(const std::string& target);

}  // namespace clr
