// SPDX-License-Identifier: MIT
#pragma once
// Derives an instrument's fingering chart from its file: every way to play each written pitch
// (valve combination or slide position × partial) from the physics in brass_physics.hpp, the
// standard one chosen by the file's conventions, the alternates after it in order of
// preference, then the file's overrides. Rules (content/instruments/README.md):
//  - valves: every subset of the valves; on every listed partial within max_partial_cents of
//    equal temperament (so a flat 7th partial is not used with valves); named by the nominal
//    lowering; listed when its tuning before correction is within max_alternate_cents.
//  - slide: position p lowers the series (of the trigger combination in use) by p − 1
//    semitones; the slide is placed where the note is in tune, which must lie between 1st and
//    the last position, give or take lip_cents (so the flat 7th partial is not used in 1st).
//  - standard: among the fingerings the first matching conventions/standard rule allows, the
//    smallest nominal lowering, then the combination preference, then the lower partial.
//  - alternates: those the rule allows first, then by tuning error, preference, lowering,
//    partial.
// Fills instrument.chart and instrument.chart_begin. Errors name the file and JSON path.

#include <tutti/brass_model/instrument_file.hpp>
#include <tutti/core/result.hpp>

namespace tutti::brass_model {

Status derive_chart(InstrumentFile& file);

}  // namespace tutti::brass_model
