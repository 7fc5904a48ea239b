// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/SocketCanPresence.h"

#include <net/if.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstring>

namespace coscope {

LinkPresence socketCanPresence(const QString& interfaceName) {
    const QByteArray name = interfaceName.toLocal8Bit();
    if (name.isEmpty() || name.size() >= IFNAMSIZ || if_nametoindex(name.constData()) == 0) return LinkPresence::Gone;
    const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
    if (fd < 0) return LinkPresence::Up;  // cannot ask: assume it is still there
    ifreq req{};
    std::memcpy(req.ifr_name, name.constData(), static_cast<size_t>(name.size()));
    const bool ok = ::ioctl(fd, SIOCGIFFLAGS, &req) == 0;
    ::close(fd);
    if (!ok) return LinkPresence::Gone;
    return (req.ifr_flags & IFF_UP) ? LinkPresence::Up : LinkPresence::Down;
}

}  // namespace coscope
