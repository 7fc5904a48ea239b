// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanBus.h"
#include "core/trace/CaptureSession.h"

#include <QMainWindow>

#include <memory>

class QLabel;
class QTableView;
class QTimer;

namespace coscope::gui {

class TraceModel;

// The main window only assembles the docks and the status bar.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Connects to a bus URL; errors are shown in the window, not only logged.
    bool connectBus(const QString& url);
    void disconnectBus();

    CanBus* bus() const { return bus_.get(); }
    TraceModel* traceModel() const { return model_; }
    QTableView* traceView() const { return view_; }

private:
    void refresh();
    void showError(const QString& message);

    std::unique_ptr<CanBus> bus_;
    std::unique_ptr<CaptureSession> session_;
    TraceModel* model_ = nullptr;
    QTableView* view_ = nullptr;
    QLabel* status_ = nullptr;
    QTimer* timer_ = nullptr;
    bool follow_ = true;
};

}  // namespace coscope::gui
