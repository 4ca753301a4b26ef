// report.html: a results folder's report.md as one page one can send by
// mail or put on a share (docs/reference/results.md, "report.html"). Self-contained:
// the pictures are embedded as data: URIs, the style is inline, and the page
// has no script, no font, no link and no request of any kind, so it reads the
// same anywhere, offline.
//
// The markdown is the subset coremodal's reports use (headings, pipe tables,
// "- " lists, paragraphs, `code`, **bold**, *emphasis*, ![alt](file.png),
// [text](target)); a link becomes its text and its target in brackets,
// because a relative target means nothing once the page has left its folder.
// A picture whose file is missing is said in words, never a broken image.
#pragma once

#include <filesystem>
#include <string>

namespace coremodal {

// The page of `markdown`; pictures are read from `folder`.
std::string report_html(const std::string& markdown, const std::filesystem::path& folder);

// Writes folder/report.html from folder/report.md, if the folder has one.
// Called by ResultsFolder::commit, so every command that writes a report.md
// gets its report.html, whichever pictures python drew.
void write_report_html(const std::filesystem::path& folder);

// RFC 4648 base64 of `bytes` (for the data: URIs).
std::string base64(const std::string& bytes);

}  // namespace coremodal
