#pragma once
#include <QList>
#include <QMap>
#include <QString>
#include <QtGlobal>
#include <optional>

namespace stepdeck {

// One axis of one controller: its index in that controller's list of axes (issue 32). The
// value says nothing about wires or windows: each model maps its axes to wire codes in its own
// table (elab::WireAxis, emis::WireAxis, the Nanotec bus addresses, LaserCodec::axisNumber),
// and the window's jog slots are ui::JogSlot. A controller has up to kMaxCount axes (a Nanotec
// bus: 254 drives, command reference 1.1). The first four have the familiar spellings
// Axis::X, Axis::Y, Axis::Z and Axis::U; a controller may name its axes otherwise
// (ControllerOptions), and axisName() is only the default name.
class Axis
{
public:
    static constexpr int kMaxCount = 254;

    constexpr Axis() = default;
    // Index 0..kMaxCount-1; nullopt outside.
    static constexpr std::optional<Axis> fromIndex(int index)
    {
        if (index < 0 || index >= kMaxCount)
            return std::nullopt;
        return Axis(quint16(index));
    }
    // For indices known to be in range (loops over a controller's axes); asserts otherwise.
    static constexpr Axis at(int index)
    {
        Q_ASSERT(index >= 0 && index < kMaxCount);
        return Axis(quint16(index));
    }
    constexpr int index() const { return m_index; }

    static const Axis X;
    static const Axis Y;
    static const Axis Z;
    static const Axis U;

    friend constexpr bool operator==(Axis a, Axis b) { return a.m_index == b.m_index; }
    friend constexpr bool operator!=(Axis a, Axis b) { return a.m_index != b.m_index; }
    friend constexpr bool operator<(Axis a, Axis b) { return a.m_index < b.m_index; }
    friend constexpr bool operator>(Axis a, Axis b) { return a.m_index > b.m_index; }
    friend constexpr bool operator<=(Axis a, Axis b) { return a.m_index <= b.m_index; }
    friend constexpr bool operator>=(Axis a, Axis b) { return a.m_index >= b.m_index; }
    friend size_t qHash(Axis a, size_t seed = 0) noexcept { return ::qHash(a.m_index, seed); }

private:
    constexpr explicit Axis(quint16 index) : m_index(index) {}
    quint16 m_index = 0;
};

inline constexpr Axis Axis::X{quint16(0)};
inline constexpr Axis Axis::Y{quint16(1)};
inline constexpr Axis Axis::Z{quint16(2)};
inline constexpr Axis Axis::U{quint16(3)};

// The default name: X, Y, Z, U for the first four, then "axis5", "axis6", ... (1-based, so
// that the name of the fifth axis says "5"). A controller's own names are in its options.
QString axisName(Axis axis);
// A default name back to its axis, case-insensitive ("x", "AXIS5").
std::optional<Axis> axisFromName(QStringView name);
// The four axes with letters: the axes of the E-LAB and EMIS boards and the model default of a
// controller that names no axes.
const QList<Axis>& letterAxes();

// Signed step counts or step rates per axis; axes not present in the map are "not addressed".
using AxisVector = QMap<Axis, qint64>;
using AxisVelocities = QMap<Axis, double>;

} // namespace stepdeck
