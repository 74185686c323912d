#include "PreviewScene.h"

namespace stepdeck::ui {

namespace {
const QString kSceneAxisNames[3] = {QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")};

bool hasAll(unsigned known, const QList<int>& axes)
{
    for (int axis : axes)
        if (!(known & (1u << axis)))
            return false;
    return true;
}

// The smallest rectangle holding both (QRectF::united ignores a rectangle of no size, which a
// single point is).
QRectF spanned(const std::optional<QRectF>& r, const QPointF& p)
{
    if (!r)
        return QRectF(p, QSizeF(0, 0));
    return QRectF(QPointF(qMin(r->left(), p.x()), qMin(r->top(), p.y())),
                  QPointF(qMax(r->right(), p.x()), qMax(r->bottom(), p.y())));
}
} // namespace

void PreviewScene::clear()
{
    m_points.clear();
    m_axes.clear();
    m_limits = {};
    m_centre.reset();
}

void PreviewScene::setPreview(const program::ProgramPreview& preview,
                              const machine::MachineDescription& machine)
{
    clear();
    for (int i = 0; i < 3; ++i) {
        const machine::MachineAxis* axis = machine.axis(kSceneAxisNames[i]);
        if (!axis)
            continue;
        m_axes << kSceneAxisNames[i];
        m_units[i] = machine::unitKey(axis->unit);
        if (axis->hasSoftLimits()) {
            // Soft limits are machine coordinates; the path is work coordinates.
            const double offset = preview.workOffsets.value(axis->name, 0.0);
            m_limits[i] = std::make_pair(*axis->softMinimum - offset, *axis->softMaximum - offset);
        }
    }
    m_points.reserve(preview.path.size());
    for (const program::PreviewPoint& p : preview.path) {
        Point point;
        point.rapid = p.rapid;
        point.line = p.line;
        for (int i = 0; i < 3; ++i) {
            const auto it = p.position.constFind(kSceneAxisNames[i]);
            if (it != p.position.cend() && m_axes.contains(kSceneAxisNames[i])) {
                point.position[i] = it.value();
                point.known |= 1u << i;
            }
        }
        m_points << point;
    }
    m_centre = computeCentre();
}

template <typename ToPlane>
void PreviewScene::softLimitBox(const ToPlane& toPlane, const QList<int>& axes,
                                QPainterPath& box) const
{
    box.clear();
    // A flat view needs both of its axes limited; the isometric one (and a turned one) draws
    // the box of the axes that are limited (an axis without limits flat at its zero) when two
    // or three are.
    int limited = 0;
    int limitedBits = 0;
    for (int axis : axes)
        if (m_limits[axis]) {
            ++limited;
            limitedBits |= 1 << axis;
        }
    if (limited < 2)
        return;
    auto corner = [&](int bits) {
        PreviewPosition p{};
        for (int axis : axes)
            if (m_limits[axis])
                p[axis] = (bits & (1 << axis)) ? m_limits[axis]->second : m_limits[axis]->first;
        return toPlane(p);
    };
    // The box's edges: corners that differ in one limited axis, each edge once.
    for (int bits = 0; bits < 8; ++bits)
        for (int axis : axes)
            if (!(bits & ~limitedBits) && m_limits[axis] && !(bits & (1 << axis))) {
                box.moveTo(corner(bits));
                box.lineTo(corner(bits | (1 << axis)));
            }
}

template <typename ToPlane>
void PreviewScene::projectWith(const ToPlane& toPlane, const QList<int>& axes, Projected& out) const
{
    // Emptied, not replaced: the lists keep their capacity and the paths their elements' memory
    // (Qt 6), so projecting again allocates nothing per point.
    out.feeds.clear();
    out.rapids.clear();
    out.points.clear();
    out.lines.clear();
    out.rapid.clear();
    out.joined.clear();
    out.start.reset();
    out.bounds.reset();
    out.points.reserve(m_points.size());
    out.lines.reserve(m_points.size());
    out.rapid.reserve(m_points.size());
    out.joined.reserve(m_points.size());
    bool previousDrawn = false;
    for (const Point& point : m_points) {
        // A point without a known position on one of the view's axes breaks the path there.
        if (!hasAll(point.known, axes)) {
            previousDrawn = false;
            continue;
        }
        const QPointF p = toPlane(point.position);
        if (previousDrawn) {
            QPainterPath& path = point.rapid ? out.rapids : out.feeds;
            const QPointF from = out.points.constLast();
            if (path.isEmpty() || path.currentPosition() != from)
                path.moveTo(from);
            path.lineTo(p);
        } else if (!out.start) {
            out.start = p;
        }
        out.joined << previousDrawn;
        out.points << p;
        out.lines << point.line;
        out.rapid << point.rapid;
        out.bounds = spanned(out.bounds, p);
        previousDrawn = true;
    }
    softLimitBox(toPlane, axes, out.softLimits);
    if (!out.softLimits.isEmpty()) {
        const QRectF box = out.softLimits.boundingRect();
        out.bounds = spanned(spanned(out.bounds, box.topLeft()), box.bottomRight());
    }
}

PreviewScene::Projected PreviewScene::project(PreviewViewKind kind) const
{
    Projected out;
    projectWith([kind](const PreviewPosition& p) { return PreviewProjection::project(kind, p); },
                PreviewProjection::axesOf(kind), out);
    return out;
}

void PreviewScene::project(const PreviewOrientation& orientation, const QList<int>& axes,
                           Projected& out) const
{
    projectWith([&orientation](const PreviewPosition& p) { return orientation.project(p); }, axes,
                out);
}

std::optional<PreviewPosition> PreviewScene::computeCentre() const
{
    std::optional<std::pair<PreviewPosition, PreviewPosition>> box; // lowest, highest
    for (const Point& point : m_points) {
        if (point.known != 7u)
            continue;
        if (!box) {
            box = std::make_pair(point.position, point.position);
            continue;
        }
        for (size_t i = 0; i < 3; ++i) {
            box->first[i] = qMin(box->first[i], point.position[i]);
            box->second[i] = qMax(box->second[i], point.position[i]);
        }
    }
    if (!box) {
        bool anyLimits = false;
        box = std::make_pair(PreviewPosition{}, PreviewPosition{});
        for (size_t i = 0; i < 3; ++i)
            if (m_limits[i]) {
                anyLimits = true;
                box->first[i] = m_limits[i]->first;
                box->second[i] = m_limits[i]->second;
            }
        if (!anyLimits)
            return std::nullopt;
    }
    PreviewPosition middle{};
    for (size_t i = 0; i < 3; ++i)
        middle[i] = (box->first[i] + box->second[i]) / 2;
    return middle;
}

QPainterPath PreviewScene::segmentsOfLine(const Projected& projected, int line)
{
    QPainterPath path;
    for (qsizetype i = 1; i < projected.points.size(); ++i) {
        if (projected.lines.at(i) != line || !projected.joined.at(i))
            continue;
        if (path.isEmpty() || path.currentPosition() != projected.points.at(i - 1))
            path.moveTo(projected.points.at(i - 1));
        path.lineTo(projected.points.at(i));
    }
    return path;
}

std::optional<QPointF> PreviewScene::projectPosition(PreviewViewKind kind,
                                                     const QMap<QString, double>& position)
{
    PreviewPosition p{};
    for (int axis : PreviewProjection::axesOf(kind)) {
        const auto it = position.constFind(kSceneAxisNames[axis]);
        if (it == position.cend())
            return std::nullopt;
        p[axis] = it.value();
    }
    return PreviewProjection::project(kind, p);
}

std::optional<QPointF> PreviewScene::projectPosition(const PreviewOrientation& orientation,
                                                     const QList<int>& axes,
                                                     const QMap<QString, double>& position)
{
    PreviewPosition p{};
    for (int axis : axes) {
        const auto it = position.constFind(kSceneAxisNames[axis]);
        if (it == position.cend())
            return std::nullopt;
        p[axis] = it.value();
    }
    return orientation.project(p);
}

QString PreviewScene::unitOf(PreviewViewKind kind) const
{
    QStringList units;
    for (int axis : PreviewProjection::axesOf(kind))
        if (!m_units[axis].isEmpty() && !units.contains(m_units[axis]))
            units << m_units[axis];
    return units.join(QLatin1Char('/'));
}

} // namespace stepdeck::ui
