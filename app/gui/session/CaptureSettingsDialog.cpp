// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/session/CaptureSettingsDialog.h"

#include "app/gui/JournalOffer.h"
#include "app/gui/session/MemoryBudget.h"
#include "core/trace/JournalFolder.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>

#include <unistd.h>

namespace coscope::gui {

namespace {
constexpr int kMaxKeepDays = 3650;
constexpr int kMaxKeepMegabytes = 16 * 1024 * 1024;  // 16 TiB

// The physical memory in MiB: the largest budget that makes sense.
int physicalMegabytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES);
    const long pageSize = ::sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || pageSize <= 0) return 1024 * 1024;
    return int(std::min<qint64>(qint64(pages) * pageSize >> 20, 1 << 30));
}
}  // namespace

CaptureSettingsDialog::CaptureSettingsDialog(QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("captureSettings"));
    setWindowTitle(tr("Capture settings"));
    QSettings s;
    const journals::CleanupPolicy policy = journalCleanupPolicy();

    budget_ = new QSpinBox(this);
    budget_->setObjectName(QStringLiteral("memoryBudget"));
    budget_->setRange(0, physicalMegabytes());
    budget_->setSuffix(tr(" MiB"));
    budget_->setSingleStep(256);
    budget_->setSpecialValueText(
        tr("Automatic (%1)").arg(QLocale().formattedDataSize(qint64(defaultTraceMemoryBudget()))));
    budget_->setValue(int(std::clamp<qlonglong>(s.value(kMemoryBudgetKey, 0).toLongLong(), 0, budget_->maximum())));
    budget_->setToolTip(tr(
        "The trace keeps at most this much in memory; older frames are read back from the capture journal when needed. "
        "0 = automatic: a quarter of the memory, at most 4 GiB."));

    keepDays_ = new QSpinBox(this);
    keepDays_->setObjectName(QStringLiteral("keepDays"));
    keepDays_->setRange(1, kMaxKeepDays);
    keepDays_->setSuffix(tr(" days"));
    keepDays_->setValue(policy.maxAgeDays);

    keepMegabytes_ = new QSpinBox(this);
    keepMegabytes_->setObjectName(QStringLiteral("keepMegabytes"));
    keepMegabytes_->setRange(1, kMaxKeepMegabytes);
    keepMegabytes_->setSuffix(tr(" MiB"));
    keepMegabytes_->setSingleStep(256);
    keepMegabytes_->setValue(int(std::min<qint64>(policy.maxTotalBytes >> 20, kMaxKeepMegabytes)));

    auto* form = new QFormLayout;
    form->addRow(tr("Trace memory budget:"), budget_);
    form->addRow(tr("Keep capture journals for:"), keepDays_);
    form->addRow(tr("Keep capture journals up to:"), keepMegabytes_);
    auto* folder = new QLabel(
        tr("Capture journals are kept in %1. Older ones are removed at start and when these settings change; "
           "a journal being written or not yet offered for reopening is never removed.")
            .arg(journals::defaultFolder()),
        this);
    folder->setWordWrap(true);
    folder->setTextInteractionFlags(Qt::TextSelectableByMouse);
    buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(folder);
    layout->addWidget(buttons_);
    connect(buttons_, &QDialogButtonBox::accepted, this, [this] {
        store();
        accept();
        emit applied();
    });
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

void CaptureSettingsDialog::store() {
    QSettings s;
    s.setValue(kMemoryBudgetKey, budget_->value());
    s.setValue(QStringLiteral("captures/keepDays"), keepDays_->value());
    s.setValue(QStringLiteral("captures/keepMegabytes"), keepMegabytes_->value());
}

}  // namespace coscope::gui
