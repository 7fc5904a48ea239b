// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/SignalPicker.h"

#include "app/gui/language/ObjectNameText.h"

#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace coscope::gui {

using dissect::SignalInfo;
using dissect::SignalKey;
using dissect::SignalScale;

namespace {
enum Column { ColName, ColObject, ColUnit, ColFactor, ColumnCount };
constexpr int kKeyRole = Qt::UserRole + 1;

QVariant keyData(const SignalKey& k) { return QVariant::fromValue(static_cast<qulonglong>(k.packed())); }
}  // namespace

SignalPicker::SignalPicker(QWidget* parent)
    : QWidget(parent), search_(new QLineEdit(this)), tree_(new QTreeWidget(this)), hint_(new QLabel(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    search_->setPlaceholderText(tr("Search signals (name, object, node)"));
    search_->setClearButtonEnabled(true);
    search_->setObjectName(QStringLiteral("signalSearch"));
    tree_->setObjectName(QStringLiteral("signalTree"));
    hint_->setObjectName(QStringLiteral("signalHint"));
    hint_->setWordWrap(true);
    hint_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    hint_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    hint_->setMargin(4);
    hint_->hide();
    layout->addWidget(search_);
    layout->addWidget(hint_);
    layout->addWidget(tree_, 1);
    tree_->setColumnCount(ColumnCount);
    tree_->setHeaderLabels({tr("Signal"), tr("Object"), tr("Unit"), tr("Factor")});
    tree_->setRootIsDecorated(true);
    tree_->setUniformRowHeights(true);
    tree_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                           QAbstractItemView::SelectedClicked);
    tree_->header()->setSectionResizeMode(ColName, QHeaderView::Stretch);
    tree_->header()->setStretchLastSection(false);
    for (int c = ColObject; c < ColumnCount; ++c)
        tree_->header()->setSectionResizeMode(c, QHeaderView::ResizeToContents);
    connect(search_, &QLineEdit::textChanged, this, &SignalPicker::applyFilter);
    connect(tree_, &QTreeWidget::itemChanged, this, &SignalPicker::onItemChanged);
}

void SignalPicker::clear() {
    catalog_.clear();
    picked_.clear();
    userScale_.clear();
    emptyHint_.clear();
    search_->clear();  // a search typed for the previous source would hide the new one's signals
    rebuildTree();
    emit pickedChanged();
}

void SignalPicker::setCatalog(const std::vector<SignalInfo>& catalog) {
    catalog_ = catalog;
    rebuildTree();
}

const SignalInfo* SignalPicker::info(const SignalKey& key) const {
    const auto it = std::find_if(catalog_.begin(), catalog_.end(), [&](const SignalInfo& i) { return i.key == key; });
    return it == catalog_.end() ? nullptr : &*it;
}

SignalScale SignalPicker::scale(const SignalKey& key) const {
    if (const auto it = userScale_.find(key); it != userScale_.end()) return it->second;
    const SignalInfo* i = info(key);
    return i ? i->scale : SignalScale{};
}

void SignalPicker::setScale(const SignalKey& key, const SignalScale& scale) {
    userScale_[key] = scale;
    rebuildTree();
    emit scaleChanged();
}

void SignalPicker::setPicked(const SignalKey& key, bool on) {
    const auto it = std::find(picked_.begin(), picked_.end(), key);
    if (on == (it != picked_.end())) return;
    if (on) picked_.push_back(key);
    else picked_.erase(it);
    rebuildTree();
    emit pickedChanged();
}

void SignalPicker::setFilter(const QString& text) { search_->setText(text); }

void SignalPicker::setEmptyHint(const QString& text) {
    if (text == emptyHint_) return;
    emptyHint_ = text;
    updateHint();
}

QString SignalPicker::hintText() const { return hint_->isVisibleTo(this) ? hint_->text() : QString(); }

void SignalPicker::updateHint() {
    QString text;
    if (catalog_.empty()) text = emptyHint_;
    else {
        bool shown = false;
        for (int i = 0; i < tree_->topLevelItemCount() && !shown; ++i) shown = !tree_->topLevelItem(i)->isHidden();
        if (!shown) text = tr("No signal matches “%1”.").arg(search_->text().trimmed());
    }
    hint_->setText(text);
    hint_->setVisible(!text.isEmpty());
}

void SignalPicker::rebuildTree() {
    updating_ = true;
    // Remember which nodes were collapsed.
    std::map<QString, bool> expanded;
    for (int i = 0; i < tree_->topLevelItemCount(); ++i)
        expanded[tree_->topLevelItem(i)->text(ColName)] = tree_->topLevelItem(i)->isExpanded();
    std::map<qulonglong, bool> wordExpanded;
    for (int i = 0; i < tree_->topLevelItemCount(); ++i)
        for (int k = 0; k < tree_->topLevelItem(i)->childCount(); ++k) {
            QTreeWidgetItem* w = tree_->topLevelItem(i)->child(k);
            wordExpanded[w->data(ColName, kKeyRole).toULongLong()] = w->isExpanded();
        }
    tree_->clear();
    QTreeWidgetItem* nodeItem = nullptr;
    QTreeWidgetItem* wordItem = nullptr;
    std::map<QString, QTreeWidgetItem*> groups;  // by title: per node, and per COB-ID for raw signals
    for (const SignalInfo& s : catalog_) {
        QString title;
        if (s.key.raw) {
            const QString cob = QString::number(s.cobId, 16).toUpper();
            title = s.key.bus ? tr("Bus %1, COB-ID %2h (raw signals)").arg(s.key.bus).arg(cob)
                              : tr("COB-ID %1h (raw signals)").arg(cob);
        } else {
            title = s.key.bus ? tr("Bus %1, node %2").arg(s.key.bus).arg(s.key.node) : tr("Node %1").arg(s.key.node);
            if (!s.dictionary.isEmpty()) title += QStringLiteral(" (%1)").arg(s.dictionary);
        }
        if (const auto g = groups.find(title); g != groups.end()) {
            nodeItem = g->second;
        } else {
            nodeItem = new QTreeWidgetItem(tree_);
            groups.emplace(title, nodeItem);
            nodeItem->setText(ColName, title);
            nodeItem->setFlags(Qt::ItemIsEnabled);
            nodeItem->setFirstColumnSpanned(true);
            const auto e = expanded.find(title);
            nodeItem->setExpanded(e == expanded.end() || e->second);
        }
        QTreeWidgetItem* parent = s.digital && wordItem ? wordItem : nodeItem;
        auto* item = new QTreeWidgetItem(parent);
        const QString name = localSignalName(s);  // the manual's name for a bundled dictionary's object
        item->setText(ColName, s.digital ? name.section(QStringLiteral(": "), 1) : name);
        item->setText(ColObject, s.digital ? QStringLiteral("bit %1").arg(s.key.bit) : s.object);
        item->setToolTip(ColObject, s.pdo);
        item->setToolTip(
            ColName,
            QStringLiteral("%1 — %2 (%3)")
                .arg(s.key.text(), name == s.name ? s.name : QStringLiteral("%1 / %2").arg(name, s.name), s.pdo));
        item->setData(ColName, kKeyRole, keyData(s.key));
        Qt::ItemFlags flags = Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable;
        if (!s.digital) {
            const SignalScale sc = scale(s.key);
            item->setText(ColUnit, sc.unit);
            item->setText(ColFactor, dissect::factorText(sc));
            item->setToolTip(
                ColFactor,
                s.key.raw
                    ? tr("value = raw × factor + %1 (defined: × %2 %3)").arg(sc.offset).arg(s.rawFactor).arg(s.rawUnit)
                    : tr("value = raw × factor (dictionary: %1 %2)").arg(s.rawFactor).arg(s.rawUnit));
            flags |= Qt::ItemIsEditable;
        }
        item->setFlags(flags);
        item->setCheckState(
            ColName, std::find(picked_.begin(), picked_.end(), s.key) != picked_.end() ? Qt::Checked : Qt::Unchecked);
        if (!s.digital) {
            wordItem = dissect::hasDigitalBits(s.key.index, s.key.sub) ? item : nullptr;
            if (wordItem) {
                const auto e = wordExpanded.find(keyData(s.key).toULongLong());
                item->setExpanded(e != wordExpanded.end() && e->second);
            }
        }
    }
    updating_ = false;
    applyFilter();
}

void SignalPicker::applyFilter() {
    const QString f = search_->text().trimmed();
    for (int i = 0; i < tree_->topLevelItemCount(); ++i) {
        QTreeWidgetItem* node = tree_->topLevelItem(i);
        const bool nodeMatches = f.isEmpty() || node->text(ColName).contains(f, Qt::CaseInsensitive);
        bool any = false;
        for (int k = 0; k < node->childCount(); ++k) {
            QTreeWidgetItem* w = node->child(k);
            bool wordAny = false;
            for (int b = 0; b < w->childCount(); ++b) {
                QTreeWidgetItem* bit = w->child(b);
                const bool m = nodeMatches || bit->text(ColName).contains(f, Qt::CaseInsensitive);
                bit->setHidden(!m);
                wordAny |= m;
            }
            const bool m = nodeMatches || wordAny || w->text(ColName).contains(f, Qt::CaseInsensitive) ||
                           w->text(ColObject).contains(f, Qt::CaseInsensitive);
            w->setHidden(!m);
            if (wordAny && !f.isEmpty()) w->setExpanded(true);
            any |= m;
        }
        node->setHidden(!any);
    }
    updateHint();
}

void SignalPicker::onItemChanged(QTreeWidgetItem* item, int column) {
    if (updating_ || !item->data(ColName, kKeyRole).isValid()) return;
    const qulonglong packed = item->data(ColName, kKeyRole).toULongLong();
    const auto it =
        std::find_if(catalog_.begin(), catalog_.end(), [&](const SignalInfo& s) { return s.key.packed() == packed; });
    if (it == catalog_.end()) return;
    const SignalKey key = it->key;
    if (column == ColName) {
        const bool on = item->checkState(ColName) == Qt::Checked;
        const auto p = std::find(picked_.begin(), picked_.end(), key);
        if (on == (p != picked_.end())) return;
        if (on) {
            picked_.push_back(key);
        } else {
            picked_.erase(p);
        }
        emit pickedChanged();
    } else if (column == ColUnit || column == ColFactor) {
        SignalScale sc = scale(key);
        if (column == ColUnit) sc.unit = item->text(ColUnit).trimmed();
        // A number or a fraction as a manual writes it ("1/1280000"); kept as typed.
        if (const auto f = dissect::parseFactor(item->text(ColFactor)); f && *f != sc.factor) {
            sc.factor = *f;
            sc.factorWritten = item->text(ColFactor).trimmed();
        }
        userScale_[key] = sc;
        updating_ = true;
        item->setText(ColFactor, dissect::factorText(sc));
        updating_ = false;
        emit scaleChanged();
    }
}

}  // namespace coscope::gui
