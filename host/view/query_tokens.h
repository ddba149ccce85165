// A request's query, read from the request's target as sent. cpp-httplib's own parse of the
// query (Request::params) drops a name=value pair given a second time, keeps only what follows
// a value's last '=', and decodes %uXXXX (which no browser writes), so that "?token=T&token=T"
// and "?token=zzz=T" would both count as the one right token, where the rule is exactly one
// token, given whole; and "?spp=4&spp=4" or "?eye=9,9,9=0,1,2" as a plain spp= or eye=.
#pragma once

#include <string>
#include <vector>

namespace clr {

// One name=value pair of a query, split at its first '=', then each side percent-decoded.
struct QueryPair {
    std::string name, value;  // value "" where the pair has no '='
    bool equals_in_value = false;  // the value held another '=' as sent (not %3D)
};

// Every pair of the query of `target` ("/path?a=1&b=2"), in order, repeats included; empty
// pairs ("a=1&&b=2", a trailing '&') are left out. %HH is decoded and '+' read as a space, as
// a browser's form encoding writes them; any other '%' stays as it is.
std::vector<QueryPair> query_pairs_as_sent(const std::string& target);

// Every token= of the query of `target`, in order, each value as it stands after the first
// '=' (decoded as above); a name matches however it is percent-encoded.
std::vector<std::string> query_tokens_as_sent(const std::string& target);

}  // namespace clr
