// The SDL gamepad backend: a held stick is sampled every 10 ms, but without a device SDL is
// only asked a few times a second whether one was plugged in (issue 21: 100 polls a second
// woke the idle GUI for nothing). No device can be plugged in here (no /dev/input): the test
// checks the state without one, as on most operator stations.
#include "TestMain.h"
#include "gamepad/SdlGamepadDevice.h"
#include <QtTest>

using namespace stepdeck::ui;

class TestSdlGamepadDevice : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void noDevice_pollsOnlyForHotplug();
};

void TestSdlGamepadDevice::noDevice_pollsOnlyForHotplug()
{
    SdlGamepadDevice device;
    if (!device.backendError().isEmpty())
        QSKIP(qPrintable(device.backendError()));
    if (device.isConnected())
        QSKIP("a gamepad is plugged in on this machine");
    QCOMPARE(device.pollIntervalMs(), SdlGamepadDevice::kIdlePollMs);
    QVERIFY(SdlGamepadDevice::kIdlePollMs > SdlGamepadDevice::kSamplePollMs);
}

STEPDECK_TEST_MAIN(TestSdlGamepadDevice)
#include "tst_sdlgamepaddevice.moc"
