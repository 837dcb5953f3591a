#pragma once
// DIR/manifest.journal: one JSON line per finished frame, appended (O(1) per frame) under the
// folder lock while a render runs. manifest.json and frames.framemd5 are rewritten from the
// journal only when a render starts and ends (consolidate_manifest), so the per-frame cost does
// not grow with the number of frames. A line whose render key differs (other settings) or that a
// kill tore (no final newline, bad JSON) is ignored: its frame is simply rendered again.
#include <string>

#include "io/manifest.h"

namespace sdfreel {

// Identity of a render's settings: equal keys <=> same_render_as.
std::string render_key(const ManifestHeader& header);

// Appends `frame` to DIR/manifest.journal; throws std::runtime_error on a failed write.
void append_journal(const std::string& dir, const std::string& key, const ManifestFrame& frame);
// Adds the journal's frames of render `key` to m.frames (indices outside the timeline skipped).
void merge_journal(const std::string& dir, const std::string& key, Manifest& m);
// The same on the journal's bytes (fuzzing uses it).
void merge_journal_text(const std::string& text, const std::string& key, Manifest& m);
// Empties the journal (after its frames went into manifest.json).
void clear_journal(const std::string& dir);

}  // namespace sdfreel
