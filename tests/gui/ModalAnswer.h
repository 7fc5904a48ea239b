// SPDX-License-Identifier: GPL-3.0-or-later
// Answers modal dialogs the way a user does (a click on a button, keys in a field), however late
// they show: an answerer waits for as long as it lives, so a loaded machine cannot make a test
// miss its dialog and hang in it. Make one before the call that shows the dialog; it stops when
// it has answered or when it goes out of scope.
#pragma once

#include <QApplication>
#include <QFileDialog>
#include <QLineEdit>
#include <QMessageBox>
#include <QPointer>
#include <QTimer>
#include <QtTest>

#include <functional>
#include <memory>

namespace coscope::testing {

class ModalAnswerer {
public:
    // `answer` gets the active modal widget and returns true when it answered it.
    explicit ModalAnswerer(std::function<bool(QWidget*)> answer) : answer_(std::move(answer)) {
        QObject::connect(&poll_, &QTimer::timeout, [this] {
            QWidget* modal = QApplication::activeModalWidget();
            if (!modal || !modal->isVisible() || seen_ == modal) return;
            if (answer_(modal)) {
                seen_ = modal;
                answered_ = true;
                poll_.stop();
            }
        });
        poll_.start(30);
    }
    bool answered() const { return answered_; }

private:
    std::function<bool(QWidget*)> answer_;
    QTimer poll_;
    QPointer<QWidget> seen_;
    bool answered_ = false;
};

// Clicks `button` in the next message box; its text goes to `*asked`. Other dialogs are left to
// their own answerers.
inline std::unique_ptr<ModalAnswerer> answerBox(QMessageBox::StandardButton button, QString* asked) {
    return std::make_unique<ModalAnswerer>([=](QWidget* w) {
        auto* box = qobject_cast<QMessageBox*>(w);
        if (!box || !box->button(button)) return false;
        *asked = box->text();
        QTest::mouseClick(box->button(button), Qt::LeftButton);
        return true;
    });
}

// Presses Escape in the next modal dialog (the "no" of a confirmation).
inline std::unique_ptr<ModalAnswerer> answerEscape(QString* asked = nullptr) {
    return std::make_unique<ModalAnswerer>([=](QWidget* w) {
        if (asked)
            if (auto* box = qobject_cast<QMessageBox*>(w)) *asked = box->text();
        QTest::keyClick(w, Qt::Key_Escape);
        return true;
    });
}

// Types `path` into the next file dialog's name field and presses Enter.
inline std::unique_ptr<ModalAnswerer> answerFileDialog(const QString& path) {
    return std::make_unique<ModalAnswerer>([=](QWidget* w) {
        auto* dialog = qobject_cast<QFileDialog*>(w);
        auto* name = dialog ? dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit")) : nullptr;
        if (!name) return false;
        QTest::keyClick(name, Qt::Key_A, Qt::ControlModifier);  // typing replaces what is there
        QTest::keyClicks(name, path);
        QTest::keyClick(name, Qt::Key_Return);
        return true;
    });
}

}  // namespace coscope::testing
