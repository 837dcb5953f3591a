#pragma once
// Where sdfreel keeps what it can make again but would rather not (content-keyed files such as
// the lenticular card's source views): $SDFREEL_CACHE_DIR, else $XDG_CACHE_HOME/sdfreel, else
// ~/.cache/sdfreel. "" when none of them is set. Tests point SDFREEL_CACHE_DIR at a scratch folder.
#include <cstdint>
#include <string>

namespace sdfreel {

std::string cache_dir();

// Names this build of the code: a hash of the running executable's bytes (a rebuild that changes
// any code changes it), computed once per process. Part of every cache key, so a cached file is
// never used by code that might have made it differently.
uint64_t build_id();

// FNV-1a over `text`: the content key of a description.
uint64_t content_key(const std::string& text);

}  // namespace sdfreel
