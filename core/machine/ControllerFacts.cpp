#include "ControllerFacts.h"
#include "Machine.h"
#include <algorithm>

namespace stepdeck::machine {

std::optional<ControllerFacts> controllerFacts(const Machine& machine, const QString& id)
{
    const ControllerSession* session = machine.session(id);
    if (!session)
        return std::nullopt;
    ControllerFacts f;
    f.capabilities = session->capabilities();
    f.schema = session->schema();
    f.model = session->model();
    f.knownParameters = session->status().knownParameters;
    const QStringList wanted = f.model ? f.model->setupBeforeMotion : QStringList{};
    const bool written =
        !wanted.isEmpty() && std::all_of(wanted.cbegin(), wanted.cend(), [&](const QString& n) {
            return f.knownParameters.contains(n);
        });
    f.setupIncomplete = session->status().setupIncomplete && !written;
    return f;
}

QStringList controllersWithoutStop(const Machine& machine)
{
    QStringList ids;
    for (const MachineController& c : machine.description().controllers)
        if (const ControllerSession* s = machine.session(c.id); s && !s->capabilities().stopCommand)
            ids << c.id;
    return ids;
}

bool linkDown(const Machine& machine, const QString& id)
{
    const ControllerSession* s = machine.session(id);
    return s && s->linkState() != LinkState::Connected;
}

} // namespace stepdeck::machine
