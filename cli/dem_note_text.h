// The command line's words for the notes on a DEM (io/dem_notes.h), with the GDAL commands that
// correct what they point out.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "io/read/dem_reader.h"

namespace tsk::cli {

// Where a DEM comes from, for the remedy a note names: a file, which GDAL's tools correct, or an
// array that a Python call passes with its keywords.
enum class DemOrigin { file, array };

std::string note_text(const io::DemNote& note, DemOrigin origin = DemOrigin::file);

// Why a DEM was refused, and the command (or for an array, the keywords) that makes it fit.
std::string refusal_text(const io::DemRefused& refused, DemOrigin origin = DemOrigin::file);

// Each note on a line of its own, after "note: ".
void print_notes(const std::vector<io::DemNote>& notes, std::ostream& err,
                 DemOrigin origin = DemOrigin::file);

}  // namespace tsk::cli
