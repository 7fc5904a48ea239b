// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for CommandScript::parse: never crashes; whatever parses prints (toText)
// and parses again to the same step lines, and every error names a line.
#include "core/canopen/CommandScript.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace coscope::canopen;
    const QString text = QString::fromUtf8(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    QString error;
    const auto script = CommandScript::parse(text, &error);
    if (!script) {
        if (!error.startsWith(QStringLiteral("line "))) __builtin_trap();
        return 0;
    }
    for (const ScriptStep& s : script->steps) (void)s.describe();
    const auto again = CommandScript::parse(script->toText(), &error);
    if (!again || again->steps.size() != script->steps.size()) __builtin_trap();
    for (size_t i = 0; i < script->steps.size(); ++i)
        if (again->steps[i].toLine() != script->steps[i].toLine()) __builtin_trap();
    return 0;
}
