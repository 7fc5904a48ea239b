// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWizardPage>

#include <cstdint>

class QLabel;
class QLineEdit;
class QListWidget;
class QListWidgetItem;

namespace coscope::gui {

class PdoWizard;
class PdoFrameLayout;

// Page 2: what the message carries. Left, the objects this drive allows in this PDO (PDO-
// mappable, readable for a TPDO / writable for an RPDO), searchable; right, the mapped objects
// in frame order (add by double-click, button or drag; reorder by drag or Up/Down); below, the
// frame byte by byte and the bit total (at most 64).
class PdoMappingPage : public QWizardPage {
    Q_OBJECT
public:
    explicit PdoMappingPage(PdoWizard* wizard);

    void initializePage() override;
    bool isComplete() const override;

    // Editing (the buttons and drag and drop use these too). False + *why when refused.
    bool addObject(uint16_t index, uint8_t sub, QString* why = nullptr);
    void removeAt(int row);
    void moveUp(int row);
    void moveDown(int row);
    void clearMapping();
    void restoreCurrent();
    void setFilter(const QString& text);

    int availableCount() const;
    int mappedCount() const;
    PdoFrameLayout* frameLayout() const { return layout_; }

private:
    void fillAvailable();
    void showMapped();    // state -> list and layout
    void syncFromList();  // list (after a drag) -> state
    void updateSummary();

    PdoWizard* wizard_;
    QLineEdit* search_;
    QListWidget* available_;
    QListWidget* mapped_;
    PdoFrameLayout* layout_;
    QLabel* summary_;
    bool showing_ = false;
    bool syncQueued_ = false;
};

}  // namespace coscope::gui
