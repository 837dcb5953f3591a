#pragma once
// Where sdfreel keeps data it can always make again (generated textures): $SDFREEL_CACHE_DIR,
// else $XDG_CACHE_HOME/sdfreel, else $HOME/.cache/sdfreel. Tests point SDFREEL_CACHE_DIR at a
// scratch folder.
#include <filesystem>

namespace sdfreel {

// The cache folder (not created here); empty when none of the variables is set (no caching).
std::filesystem::path cache_dir();

}  // namespace sdfreel
