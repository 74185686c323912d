// Sequencing of exchanges with the drives (NanotecSteps.h).
#include "NanotecSteps.h"
#include "Logging.h"
#include "NanotecCodec.h"
#include "NanotecController.h"
#include "NanotecLogging.h"

namespace stepdeck::nanotec {

namespace {
void runFrom(std::shared_ptr<QList<Step>> steps, int index, Done done)
{
    if (index >= steps->size()) {
        done({});
        return;
    }
    (*steps)[index]([steps, index, done](const Failure& f) {
        if (!f.ok())
            done(f);
        else
            runFrom(steps, index + 1, done);
    });
}
} // namespace

void runSteps(QList<Step> steps, Done done)
{
    runFrom(std::make_shared<QList<Step>>(std::move(steps)), 0, std::move(done));
}

Step tolerant(Step step)
{
    return [step](const Done& done) {
        step([done](const Failure& f) {
            if (!f.ok() && f.kind != ErrorKind::Cancelled)
                qCInfo(lcNanotec) << "ignored:" << f.message;
            done(f.kind == ErrorKind::Cancelled ? f : Failure{});
        });
    };
}

Check sink(std::function<void(qint64)> store)
{
    return [store](const Reply& r) {
        if (!r.value)
            return Failure{ErrorKind::Protocol, NanotecController::tr("reply '%1' carries no value")
                                                    .arg(QString::fromLatin1(r.raw))};
        store(*r.value);
        return Failure{};
    };
}

} // namespace stepdeck::nanotec
