// SPDX-License-Identifier: GPL-3.0-or-later
#include "eds/SimulatorDictionaries.h"

#include "core/sim/DictionaryProvider.h"
#include "eds/DictionaryLibrary.h"

#include <spdlog/spdlog.h>

namespace coscope::eds {

void installSimulatorDictionaries() {
    sim::setDictionaryProvider([](const QString& name, QString* error) -> std::optional<od::ObjectDictionary> {
        const DictionaryLibrary library;
        if (!library.find(name)) {
            if (error) *error = QStringLiteral("no dictionary named '%1' in the dictionary library").arg(name);
            return std::nullopt;
        }
        ReadResult result = library.load(name);
        if (!result.usable) {
            if (error)
                *error =
                    QStringLiteral("dictionary '%1' could not be read (%2 errors)").arg(name).arg(result.errorCount());
            return std::nullopt;
        }
        if (result.errorCount() > 0)
            spdlog::warn("simulator dictionary {}: {} errors, {} warnings", name.toStdString(), result.errorCount(),
                         result.warningCount());
        return std::move(result.dictionary);
    });
}

}  // namespace coscope::eds
