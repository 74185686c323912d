#include "TransportFactory.h"
#include "SerialTransport.h"
#include "TcpTransport.h"

namespace stepdeck {

Transport* createTransport(const QString& port, QObject* parent)
{
    if (port.startsWith(QLatin1String("tcp://")))
        return new TcpTransport(port, parent);
    return new SerialTransport(port, parent);
}

} // namespace stepdeck
