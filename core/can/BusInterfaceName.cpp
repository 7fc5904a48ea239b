// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/BusInterfaceName.h"

#include <QFileInfo>

namespace coscope {

QString busInterfaceName(const BusUrl& url) {
    QString name;
    if (url.scheme == u"sim") name = QStringLiteral("sim");
    else if (url.scheme == u"socketcand") name = url.channel;
    else if (url.scheme == u"replay") name = QFileInfo(url.target).completeBaseName();
    else name = url.target;
    // candump -L fields are separated by spaces: keep the name one field.
    name.replace(u' ', u'_');
    return name.isEmpty() ? url.scheme : name;
}

}  // namespace coscope
