#!/bin/sh
# lupdate the zh .ts files like the update_translations target (GUI sources, no locations, no
# obsolete entries), fill new messages from TABLE.json (fill_ts.py) and lupdate again for its layout.
# Usage: scripts/l10n/update.sh [TABLE.json]
set -e
cd "$(dirname "$0")/../.."
# The build's target, not lupdate over app/gui: only with the GUI library's include paths does
# lupdate name the contexts as tr() looks them up at run time (coscope::gui::MainWindow).
run_lupdate() {
    cmake --build --preset dev --target update_translations >/dev/null
}
run_lupdate
if [ -n "$1" ]; then
    python3 scripts/l10n/fill_ts.py "$1" resources/translations
    run_lupdate
fi
python3 scripts/l10n/check_ts.py resources/translations/coscope_zh_TW.ts resources/translations/coscope_zh_CN.ts
