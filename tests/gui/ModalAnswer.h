// SPDX-License-Identifier: GPL-3.0-or-later
// Answers modal dialogs the way a user does (a click on a button, keys in a field), however late
// they show: an answerer waits for as long as it lives, so a loaded machine cannot make a test
// miss its dialog and hang in it. Make one before the call that shows the dialog; it stops when
// it has answered or when it goes out of scope.
#pragma once

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QApplication>
#include <QCompleter>
#include <QDialogButtonBox>
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
            if (seen_ || answered_) {
                // Answered: done once that dialog is gone; if it is still up after a while (a
                // completer popup took the Enter, say), answer it again as a user would.
                if (!seen_ || !seen_->isVisible()) return poll_.stop();
                if (++waited_ < 20 || QApplication::activeModalWidget() != seen_) return;
                waited_ = 0;
                answer_(seen_);
                return;
            }
            QWidget* modal = QApplication::activeModalWidget();
            if (!modal || !modal->isVisible()) return;
            if (answer_(modal)) {
                seen_ = modal;
                answered_ = true;
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
    int waited_ = 0;
};

// Clicks `button` in the next message box; its text goes to `*asked`. Other dialogs are left to
// their own answerers.
inline std::unique_ptr<ModalAnswerer> answerBox(QMessageBox::StandardButton button, QString* asked = nullptr) {
    return std::make_unique<ModalAnswerer>([=](QWidget* w) {
        auto* box = qobject_cast<QMessageBox*>(w);
        if (!box || !box->button(button)) return false;
        if (asked) *asked = box->text();
        QTest::mouseClick(box->button(button), Qt::LeftButton);
        return true;
    });
}

// Clicks `button` in the next message box whose text holds `says`; its text goes to `*asked`.
// Boxes that say something else are left to other answerers.
inline std::unique_ptr<ModalAnswerer> answerBoxSaying(const QString& says, QMessageBox::StandardButton button,
                                                      QString* asked = nullptr) {
    return std::make_unique<ModalAnswerer>([=](QWidget* w) {
        auto* box = qobject_cast<QMessageBox*>(w);
        if (!box || !box->text().contains(says) || !box->button(button)) return false;
        if (asked) *asked = box->text();
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

// Types `path` into the next file dialog's name field and clicks its Open/Save button.
inline std::unique_ptr<ModalAnswerer> answerFileDialog(const QString& path) {
    auto clicked = std::make_shared<QPointer<QFileDialog>>();
    return std::make_unique<ModalAnswerer>([=](QWidget* w) {
        auto* dialog = qobject_cast<QFileDialog*>(w);
        if (dialog && *clicked == dialog) {
            // Clicked and still open: Qt's own dialog sometimes drops the click while it re-lists
            // its folder (offscreen runs); then choose the file through the dialog's own API.
            dialog->selectFile(path);
            static_cast<QDialog*>(dialog)->accept();  // QFileDialog::accept, as its Save button does
            return true;
        }
        auto* name = dialog ? dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit")) : nullptr;
        auto* buttons = dialog ? dialog->findChild<QDialogButtonBox*>(QStringLiteral("buttonBox")) : nullptr;
        if (!name || !buttons) return false;
        QTest::keyClick(name, Qt::Key_A, Qt::ControlModifier);  // typing replaces what is there
        QTest::keyClicks(name, path);
        // The name completer may have popped up over the field: Escape closes only the popup.
        if (QCompleter* c = name->completer(); c && c->popup() && c->popup()->isVisible())
            QTest::keyClick(c->popup(), Qt::Key_Escape);
        QAbstractButton* accept = nullptr;
        for (QAbstractButton* b : buttons->buttons())
            if (buttons->buttonRole(b) == QDialogButtonBox::AcceptRole) accept = b;
        // The dialog may still be listing its folder (the button is off, the name was reset):
        // not answered yet, the next tick types again.
        if (!accept || !accept->isEnabled() || name->text() != path) return false;
        *clicked = dialog;
        QTest::mouseClick(accept, Qt::LeftButton);
        return true;
    });
}

}  // namespace coscope::testing
