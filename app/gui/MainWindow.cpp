// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/MainWindow.h"

#include "app/gui/trace/TraceModel.h"

#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QScrollBar>
#include <QStatusBar>
#include <QTableView>
#include <QTimer>

#include <spdlog/spdlog.h>

namespace coscope::gui {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(QStringLiteral("CoScope"));
    resize(1100, 700);
    model_ = new TraceModel(this);
    view_ = new QTableView(this);
    view_->setModel(model_);
    view_->verticalHeader()->hide();
    view_->verticalHeader()->setDefaultSectionSize(20);
    view_->horizontalHeader()->setStretchLastSection(true);
    view_->setSelectionBehavior(QAbstractItemView::SelectRows);
    view_->setColumnWidth(TraceModel::Number, 80);
    view_->setColumnWidth(TraceModel::Time, 110);
    view_->setColumnWidth(TraceModel::Bus, 40);
    view_->setColumnWidth(TraceModel::CobId, 90);
    view_->setColumnWidth(TraceModel::Direction, 40);
    view_->setColumnWidth(TraceModel::Length, 40);
    setCentralWidget(view_);
    status_ = new QLabel(this);
    statusBar()->addPermanentWidget(status_, 1);
    timer_ = new QTimer(this);
    timer_->setInterval(33);  // the GUI pulls at most 30 times a second
    connect(timer_, &QTimer::timeout, this, &MainWindow::refresh);
    timer_->start();
}

MainWindow::~MainWindow() { disconnectBus(); }

bool MainWindow::connectBus(const QString& url) {
    disconnectBus();
    QString error;
    bus_ = createBus(url, &error);
    if (!bus_) {
        showError(error);
        return false;
    }
    connect(bus_.get(), &CanBus::errorOccurred, this, &MainWindow::showError);
    session_ = std::make_unique<CaptureSession>();
    model_->setStore(session_->store());
    session_->start(bus_.get());
    bus_->open();
    setWindowTitle(QStringLiteral("CoScope — %1").arg(url));
    return true;
}

void MainWindow::disconnectBus() {
    if (bus_) bus_->close();
    if (session_) session_->stop();
    bus_.reset();
}

void MainWindow::refresh() {
    model_->refresh();
    if (follow_ && model_->rowCount() > 0) view_->scrollToBottom();
    if (bus_) {
        const auto c = bus_->counters();
        status_->setText(QStringLiteral("%1   %2   rx %3   tx %4   dropped %5   errors %6")
                             .arg(bus_->url().toString(), toString(bus_->state()))
                             .arg(c.rx)
                             .arg(c.tx)
                             .arg(c.dropped)
                             .arg(c.errors));
    }
}

void MainWindow::showError(const QString& message) {
    spdlog::error("{}", message.toStdString());
    statusBar()->showMessage(message, 10000);
}

}  // namespace coscope::gui
