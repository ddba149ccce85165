// The secret that every request to `clrender view` must carry: 128 random bits from the
// operating system, as 32 hexadecimal digits. Another user on the machine, or a web page the
// user visits, cannot guess it, so only who was given the printed address can drive the viewer.
#pragma once

#include <string>
#include <string_view>

namespace clr {

// 32 lowercase hex digits from getrandom() (the kernel's CSPRNG). Throws std::runtime_error
// when the system gives no random bytes: the viewer must not start with a guessable token.
std::string make_access_token();

// Whether `given` is `token`, in time that does not depend on where they differ (a timing
// side channel must not reveal the token digit by digit).
bool token_matches(std::string_view given, std::string_view token);

}  // namespace clr
