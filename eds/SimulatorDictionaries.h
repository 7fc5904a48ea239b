// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace coscope::eds {

// Installs the simulator's dictionary provider (sim::setDictionaryProvider): virtual devices are
// built from the dictionaries of the DictionaryLibrary (bundled ones, or the user's file of the
// same name). Call once at start-up, before opening a sim:// bus. Safe to call again.
void installSimulatorDictionaries();

}  // namespace coscope::eds
