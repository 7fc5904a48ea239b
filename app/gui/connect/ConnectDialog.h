// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/connect/ owns choosing a bus to open: the connect dialog (bus URL, bit rate,
// listen-only) and the recent connections.
#pragma once

#include "core/can/SocketCanLinkJob.h"
#include "core/can/SocketCanLinks.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QStackedWidget;
class QTableWidget;

namespace coscope::gui {

// Choose a bus: a Qt CAN plugin and its device, a socketcand server, the virtual drives (sim://)
// or a log replay, with bit rate, CAN FD and listen-only. Builds the same URL string the CLI
// takes (DESIGN.md "Bus URLs"); recent connections are one click away.
class ConnectDialog : public QDialog {
    Q_OBJECT
public:
    explicit ConnectDialog(QWidget* parent = nullptr);

    QString url() const;               // the URL the choices make
    void setUrl(const QString& text);  // fills the choices from a URL (recent connections)

    // Backend keys in the combo: "sim", "socketcand", "replay", or a Qt plugin name.
    QComboBox* backend() const { return backend_; }
    QCheckBox* listenOnly() const { return listenOnly_; }
    QTableWidget* drives() const { return drives_; }

    void accept() override;  // validates the URL first

private:
    void onBackendChanged();
    void updatePreview();
    void onUrlTyped(const QString& text);  // a pasted or typed URL fills the choices
    void updateLinkState();                // the chosen interface's state and how to bring it up
    QString linkText(const SocketCanLink& link) const;
    void onLinksListed(const QList<SocketCanLink>& links, const QString& error);
    void onBringUp();
    void onBroughtUp(bool ok, const QString& error);

    QComboBox* recent_ = nullptr;
    QComboBox* backend_ = nullptr;
    QStackedWidget* pages_ = nullptr;
    QComboBox* device_ = nullptr;
    QLineEdit* host_ = nullptr;
    QSpinBox* port_ = nullptr;
    QLineEdit* channel_ = nullptr;
    QTableWidget* drives_ = nullptr;
    QLabel* noDevices_ = nullptr;
    QLabel* linkState_ = nullptr;
    QList<SocketCanLink> links_;  // SocketCAN interfaces as `ip -details -json link` reports them
    SocketCanLinkJob* linkJob_ = nullptr;
    QPushButton* bringUp_ = nullptr;
    bool mayConfigure_ = false;
    QLineEdit* replayPath_ = nullptr;
    QComboBox* replaySpeed_ = nullptr;
    QCheckBox* replayLoop_ = nullptr;
    QComboBox* bitrate_ = nullptr;
    QCheckBox* fd_ = nullptr;
    QComboBox* dataBitrate_ = nullptr;
    QCheckBox* listenOnly_ = nullptr;
    QLineEdit* preview_ = nullptr;
    QLabel* error_ = nullptr;
    QString typed_;  // the URL as typed/pasted, used as-is until a choice changes
    bool applyingTyped_ = false;
};

}  // namespace coscope::gui
