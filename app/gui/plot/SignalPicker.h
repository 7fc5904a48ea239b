// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "dissectors/SignalCatalog.h"

#include <QWidget>

#include <map>
#include <optional>
#include <vector>

class QLabel;
class QLineEdit;
class QTreeWidget;
class QTreeWidgetItem;

namespace coscope::gui {

// The signal list of the Plot dock: per node the objects its PDOs carry (and the bits of
// 6040h/6041h under their word), with a search box. A check box picks a signal; the Unit and
// Factor columns are editable (the engineering scale: value = raw x factor).
class SignalPicker : public QWidget {
    Q_OBJECT
public:
    explicit SignalPicker(QWidget* parent = nullptr);

    // Merges a new catalogue, keeping picks and the user's scales.
    void setCatalog(const std::vector<dissect::SignalInfo>& catalog);
    void clear();
    const std::vector<dissect::SignalInfo>& catalog() const { return catalog_; }

    std::vector<dissect::SignalKey> picked() const { return picked_; }  // in the order picked
    void setPicked(const dissect::SignalKey& key, bool on);
    const dissect::SignalInfo* info(const dissect::SignalKey& key) const;
    // The scale in force: the user's, else the catalogue's default.
    dissect::SignalScale scale(const dissect::SignalKey& key) const;
    void setScale(const dissect::SignalKey& key, const dissect::SignalScale& scale);
    void setFilter(const QString& text);
    // What the list says instead of signals while the catalogue is empty (why, and what could
    // be plotted); the picker itself says when the search hides every signal.
    void setEmptyHint(const QString& text);
    QString hintText() const;  // what the user reads above the list ("" = none shown)

signals:
    void pickedChanged();
    void scaleChanged();

private:
    void rebuildTree();
    void applyFilter();
    void updateHint();
    void onItemChanged(QTreeWidgetItem* item, int column);

    QLineEdit* search_;
    QTreeWidget* tree_;
    QLabel* hint_;
    QString emptyHint_;
    std::vector<dissect::SignalInfo> catalog_;
    std::vector<dissect::SignalKey> picked_;
    std::map<dissect::SignalKey, dissect::SignalScale> userScale_;
    bool updating_ = false;
};

}  // namespace coscope::gui
