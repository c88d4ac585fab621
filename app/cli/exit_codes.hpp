#pragma once

namespace tutti::app {

inline constexpr int kExitOk = 0;
// Bad input (unreadable, broken or hostile file) and bad usage: the message says which.
inline constexpr int kExitBadInput = 2;

}  // namespace tutti::app
