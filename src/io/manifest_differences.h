#pragma once
// What keeps two renders' frames from being interchangeable, field by field, so that `verify`
// can say "versions.mesa: 25.0.7 here, 22.3.6 in the manifest" instead of "other settings".
#include <string>
#include <vector>

#include "io/manifest.h"

namespace sdfreel {

// One line per field of ManifestHeader::same_render_as that differs (versions key by key), in
// the form "FIELD: HERE here, THERE in the manifest"; empty when the renders are the same.
std::vector<std::string> header_differences(const ManifestHeader& here,
                                            const ManifestHeader& manifest);

}  // namespace sdfreel
