// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDockWidget>

namespace coscope::gui {

class Workspace;

// The Object Dictionary dock: the selected node's dictionary as a tree (index/sub, name, type,
// access, PDO-mappable, default, actual value, unit), read and written over SDO through the
// core services.
class ObjectDictionaryDock : public QDockWidget {
    Q_OBJECT
public:
    explicit ObjectDictionaryDock(Workspace* workspace, QWidget* parent = nullptr);

    void rebind();   // the workspace's source changed
    void refresh();  // the window's ≤ 30 Hz tick
    void setNode(int node);  // -1 = none
    int node() const { return node_; }
    // True when there is something worth a screenshot (a node's dictionary with values).
    bool hasContent() const;

signals:
    void message(const QString& text);

private:
    Workspace* workspace_;
    int node_ = -1;
};

}  // namespace coscope::gui
