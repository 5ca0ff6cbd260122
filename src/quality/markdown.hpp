// The report of `moa check --report`: a Markdown page for people and CI artifacts.
#pragma once

#include <string>

#include "quality/quality.hpp"

namespace moa {

// The report's numbers as Markdown tables: the title names `mesh_name`; the smallest-angle
// histogram is shown as the picture `histogram_image` (a path relative to the page; none when
// empty) and as a table.
std::string report_to_markdown(const MeshReport &report, const std::string &mesh_name,
                               const std::string &histogram_image);

}  // namespace moa
