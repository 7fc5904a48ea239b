#!/bin/sh
# lupdate the zh .ts files like the update_translations target (GUI sources, no locations, no
# obsolete entries), fill new messages from TABLE.json (fill_ts.py) and lupdate again for its layout.
# Usage: scripts/l10n/update.sh [TABLE.json]
set -e
cd "$(dirname "$0")/../.."
LUPDATE=/usr/lib/qt6/bin/lupdate
run_lupdate() {
    for l in zh_TW zh_CN; do
        "$LUPDATE" -silent app/gui -ts resources/translations/coscope_$l.ts -target-language $l \
            -locations none -no-ui-lines -no-obsolete
    done
}
run_lupdate
if [ -n "$1" ]; then
    python3 scripts/l10n/fill_ts.py "$1" resources/translations
    run_lupdate
fi
python3 scripts/l10n/check_ts.py resources/translations/coscope_zh_TW.ts resources/translations/coscope_zh_CN.ts
