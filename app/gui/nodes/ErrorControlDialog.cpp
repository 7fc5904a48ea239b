// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/nodes/ErrorControlDialog.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QRadioButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>

namespace coscope::gui {

namespace {
QSpinBox* msBox(const QString& name, int min, int value, QWidget* parent) {
    auto* box = new QSpinBox(parent);
    box->setObjectName(name);
    box->setRange(min, 65535);  // 1016h / 100Ch hold 16-bit milliseconds (CiA 301 §7.5.2.4, §7.5.2.18)
    box->setSuffix(ErrorControlDialog::tr(" ms"));
    box->setValue(value);
    return box;
}
}  // namespace

ErrorControlDialog::ErrorControlDialog(const canopen::NodeInfo& node, const QString& guardingOffWhy, QWidget* parent)
    : QDialog(parent) {
    setObjectName(QStringLiteral("errorControlDialog"));
    setWindowTitle(tr("Heartbeat and guarding of node %1").arg(node.node));
    const canopen::ErrorControlWatch& w = node.watch;
    // A heartbeat seen: 3 x its period by default, as CoScope's own heartbeat guard does.
    const int periodMs = static_cast<int>(node.heartbeatPeriodNs / 1'000'000);
    const int consumer = w.consumerTimeMs ? w.consumerTimeMs
                         : periodMs > 0   ? std::clamp(3 * periodMs, 100, 65535)
                                          : 1000;

    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(
        tr("How CoScope watches that node %1 is there (CiA 301 error control). A lost node is raised in the Events.")
            .arg(node.node),
        this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    none_ = new QRadioButton(tr("Not watched"), this);
    none_->setObjectName(QStringLiteral("watchNone"));
    layout->addWidget(none_);

    heartbeat_ = new QRadioButton(tr("Heartbeat: the node sends it (1017h); lost when none comes within"), this);
    heartbeat_->setObjectName(QStringLiteral("watchHeartbeat"));
    layout->addWidget(heartbeat_);
    auto* hbForm = new QFormLayout;
    consumerTime_ = msBox(QStringLiteral("consumerTime"), 10, consumer, this);
    hbForm->addRow(tr("Consumer time:"), consumerTime_);
    layout->addLayout(hbForm);

    guarding_ =
        new QRadioButton(tr("Node guarding, for a node without heartbeat: CoScope asks (RTR on %1h) every guard time")
                             .arg(QString::number(0x700 + node.node, 16).toUpper()),
                         this);
    guarding_->setObjectName(QStringLiteral("watchGuarding"));
    layout->addWidget(guarding_);
    auto* gForm = new QFormLayout;
    guardTime_ = msBox(QStringLiteral("guardTime"), 10, w.guardTimeMs ? w.guardTimeMs : 100, this);
    lifeFactor_ = new QSpinBox(this);
    lifeFactor_->setObjectName(QStringLiteral("lifeTimeFactor"));
    lifeFactor_->setRange(1, 255);  // 100Dh is UNSIGNED8
    lifeFactor_->setValue(w.lifeTimeFactor ? w.lifeTimeFactor : 3);
    lifeTime_ = new QLabel(this);
    gForm->addRow(tr("Guard time (100Ch):"), guardTime_);
    gForm->addRow(tr("Life time factor (100Dh):"), lifeFactor_);
    gForm->addRow(tr("Lost after:"), lifeTime_);
    layout->addLayout(gForm);

    if (!guardingOffWhy.isEmpty()) {
        guarding_->setEnabled(false);
        guarding_->setToolTip(guardingOffWhy);
        auto* why = new QLabel(guardingOffWhy, this);
        why->setWordWrap(true);
        layout->addWidget(why);
    } else if (node.seenHeartbeat) {
        auto* note = new QLabel(tr("Node %1 sends a heartbeat. CiA 301 guards only nodes without one (1017h = 0): "
                                   "while it sends both, its heartbeats "
                                   "can be taken for guarding answers.")
                                    .arg(node.node),
                                this);
        note->setWordWrap(true);
        layout->addWidget(note);
    }

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);

    (w.guarding() && guarding_->isEnabled() ? guarding_ : w.consumerTimeMs ? heartbeat_ : none_)->setChecked(true);
    for (QRadioButton* r : {none_, heartbeat_, guarding_})
        connect(r, &QRadioButton::toggled, this, &ErrorControlDialog::updateEnabled);
    for (QSpinBox* b : {guardTime_, lifeFactor_})
        connect(b, &QSpinBox::valueChanged, this, &ErrorControlDialog::updateEnabled);
    updateEnabled();
}

void ErrorControlDialog::updateEnabled() {
    consumerTime_->setEnabled(heartbeat_->isChecked());
    guardTime_->setEnabled(guarding_->isChecked());
    lifeFactor_->setEnabled(guarding_->isChecked());
    // Node life time = guard time x life time factor (CiA 301 §7.2.8.3.2.1).
    lifeTime_->setText(tr("%L1 ms without an answer").arg(guardTime_->value() * lifeFactor_->value()));
}

ErrorControlDialog::Choice ErrorControlDialog::choice() const {
    Choice c;
    if (heartbeat_->isChecked()) {
        c.kind = Kind::Heartbeat;
        c.consumerTimeMs = consumerTime_->value();
    } else if (guarding_->isChecked()) {
        c.kind = Kind::Guarding;
        c.guardTimeMs = guardTime_->value();
        c.lifeTimeFactor = lifeFactor_->value();
    }
    return c;
}

}  // namespace coscope::gui
