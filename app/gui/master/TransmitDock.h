// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDockWidget>

#include <set>

class QLabel;
class QLineEdit;
class QPushButton;
class QTableView;

namespace coscope {
struct CanFrame;
}
namespace coscope::od {
class ObjectDictionary;
}
namespace coscope::canopen {
struct RpdoAddress;
}

namespace coscope::gui {

class TransmitModel;
class Workspace;

// The Transmit panel (View ▸ Transmit): a list of frames to send, typed in candump syntax
// (601#4018100100000000, 123#R, 123##1AABB for CAN FD with BRS) or edited field by field in the
// table; each row sent once (Send, or Enter on the row) or every N ms while its Periodic box is
// checked, several at once, with a sent count. The rows are kept between sessions. Disabled,
// with the reason, without an open bus and on a listen-only bus. A frame aimed at the RPDO of a
// node whose mapping carries a motion object (6040h, 607Ah, 60FFh, 6071h, 60C1h…) asks once
// for confirmation, as other motion does. Sending goes through core (TransmitList on the bus's
// PeriodicSender), like `coscope-cli send`.
class TransmitDock : public QDockWidget {
    Q_OBJECT
public:
    explicit TransmitDock(Workspace* workspace, QWidget* parent = nullptr);

    void rebind();   // the source changed
    void refresh();  // the window's tick

    TransmitModel* model() const { return model_; }
    QTableView* view() const { return view_; }
    QLineEdit* frameEdit() const { return frameEdit_; }
    QLineEdit* everyEdit() const { return every_; }
    QLabel* banner() const { return banner_; }

signals:
    void message(const QString& text);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void addTyped(bool sendNow);
    void sendRows();
    void removeRows();
    void setRunning(int row, bool on);
    QList<int> selectedRows() const;
    // Motion (see class comment): true when the row may go out; asks once per row.
    bool confirmMotion(int row);
    void noteControlword(const CanFrame& frame, const canopen::RpdoAddress& aimed,
                         const od::ObjectDictionary* dictionary);
    void showError(const QString& text);

    Workspace* workspace_;
    TransmitModel* model_ = nullptr;
    QTableView* view_ = nullptr;
    QLineEdit* frameEdit_ = nullptr;
    QLineEdit* every_ = nullptr;
    QLabel* banner_ = nullptr;
    QLabel* status_ = nullptr;
    QPushButton* add_ = nullptr;
    QPushButton* send_ = nullptr;
    QPushButton* remove_ = nullptr;
    QPushButton* stopAll_ = nullptr;
    QWidget* body_ = nullptr;
    std::set<QString> confirmed_;  // frames the user allowed to move a motor (per bus)
    const void* boundList_ = nullptr;
};

}  // namespace coscope::gui
