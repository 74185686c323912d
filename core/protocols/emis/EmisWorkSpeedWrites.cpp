#include "EmisWorkSpeedWrites.h"

namespace stepdeck::emis {

void writeWorkSpeed(EmisLink& link, EmisWorkSpeeds& speeds, const EmisWorkSpeeds::Write& write,
                    EmisLink::Handler then)
{
    speeds.noteWriting(write.axis);
    EmisLink::Request r;
    r.bytes = encode::workSpeed(write.axis, write.speed);
    r.expect = EmisLink::Expect::Ack;
    r.done = [&speeds, write, then](const EmisLink::Result& result) {
        if (result.outcome == EmisLink::Outcome::Ok)
            speeds.noteOnBoard(write.axis, write.speed);
        else // refused, or no reply: whether the board took it is not known
            speeds.forgetBoard(write.axis);
        if (then)
            then(result);
    };
    link.submit(std::move(r));
}

std::shared_ptr<SpeedWriteFailure> queueMoveSpeeds(EmisLink& link, EmisWorkSpeeds& speeds,
                                                   const QList<Axis>& axes)
{
    const auto failed = std::make_shared<SpeedWriteFailure>();
    for (const EmisWorkSpeeds::Write& w : speeds.writesForMove(axes)) {
        writeWorkSpeed(link, speeds, w, [failed, w](const EmisLink::Result& r) {
            if (r.outcome != EmisLink::Outcome::Ok && !*failed)
                *failed = qMakePair(encode::workSpeed(w.axis, w.speed), r);
        });
    }
    return failed;
}

} // namespace stepdeck::emis
