#pragma once
// The programs in LinuxCNC's language of tests/core/program/ngc/ (issue 33), and the moves and
// messages each must give, worked out here from the programs' numbers with plain C++ (cos, sin,
// loops), independently of core/program/language: shared by tst_ngcprograms (the check, the
// preview, the blocks read back) and tst_ngcrun (what the devices saw).
#include <QFile>
#include <QList>
#include <QString>
#include <QStringList>
#include <QtMath>
#include <cmath>
#include <optional>

namespace stepdeck::program::ngctest {

// One G0 or G1 block: its source line and the words on it (work coordinates, mm).
struct Move
{
    int line = 0;
    bool rapid = false;
    std::optional<double> x, y, z;
};

// A (DEBUG, …) or (PRINT, …) line as the operator reads it: its source line and its text.
struct Message
{
    int line = 0;
    QString text;
    bool operator==(const Message& o) const { return line == o.line && text == o.text; }
};

struct Expected
{
    QList<Move> moves;
    QList<Message> messages;
};

struct Point
{
    double x = 0, y = 0, z = 0;
};

inline QString ngcPath(const QString& name)
{
    return QStringLiteral(STEPDECK_SOURCE_DIR "/tests/core/program/ngc/") + name;
}

inline QByteArray ngcText(const QString& name)
{
    QFile f(ngcPath(name));
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

inline QStringList sourceLines(const QByteArray& text)
{
    QStringList lines = QString::fromUtf8(text).split(QLatin1Char('\n'));
    if (!lines.isEmpty() && lines.last().isEmpty())
        lines.removeLast();
    return lines;
}

// The 1-based number of the first line after line `after` that reads `text` (white space
// around it left out); 0: none.
inline int lineOf(const QStringList& lines, const QString& text, int after = 0)
{
    for (int i = after; i < lines.size(); ++i)
        if (lines.at(i).trimmed() == text)
            return i + 1;
    return 0;
}

// A value as a message shows it: at most six decimals, no trailing zeros.
inline QString shown(double value)
{
    QString s = QString::number(value, 'f', 6);
    while (s.contains(QLatin1Char('.')) && (s.endsWith(QLatin1Char('0')) || s.endsWith('.')))
        s.chop(1);
    return s == QLatin1String("-0") ? QStringLiteral("0") : s;
}

inline Move rapid(int line, std::optional<double> x, std::optional<double> y,
                  std::optional<double> z = std::nullopt)
{
    return Move{line, true, x, y, z};
}

inline Move feed(int line, std::optional<double> x, std::optional<double> y,
                 std::optional<double> z = std::nullopt)
{
    return Move{line, false, x, y, z};
}

// bolt-circle.ngc: 6 holes on a circle of 12 mm around (30, 25), the first at 15°, 3 mm deep,
// clearance 2 mm. `radius`: the circle's (a broken copy's).
inline Expected boltCircle(const QStringList& lines, double radius = 12)
{
    const int clear = lineOf(lines, "G0 Z#<clear>");
    const int over = lineOf(lines, "G0 X#<x> Y#<y>");
    const int plunge = lineOf(lines, "G1 Z#<depth> F300");
    const int out = lineOf(lines, "G0 Z#<clear>", over);
    const int debug = lineOf(lines, "(DEBUG, hole #<i> at X#<x> Y#<y>)");
    Expected e;
    e.moves << rapid(clear, {}, {}, 2);
    for (int i = 0; i < 6; ++i) {
        const double angle = qDegreesToRadians(15.0 + i * 60.0);
        const double x = 30 + radius * std::cos(angle);
        const double y = 25 + radius * std::sin(angle);
        e.messages << Message{
            debug,
            QStringLiteral("hole %1 at X%2 Y%3").arg(QString::number(i), shown(x), shown(y))};
        e.moves << rapid(over, x, y) << feed(plunge, {}, {}, -3) << rapid(out, {}, {}, 2);
    }
    e.moves << rapid(lineOf(lines, "G0 X#<cx> Y#<cy>"), 30, 25);
    return e;
}

// pocket-sub.ngc: o<pocket> at (10, 8) 6 x 4 mm, 2 deep, then at (22, 10) 5 x 3 mm, 1.5 deep;
// levels 1 mm apart (the last shorter), passes along Y at most 2 mm apart in a zigzag.
inline Expected pocketSub(const QStringList& lines)
{
    const int over = lineOf(lines, "G0 X#<x0> Y#<y0>");
    const int down = lineOf(lines, "G1 Z#<z> F300");
    const int up = lineOf(lines, "G1 Y[#<y0> + #<height>] F600");
    const int back = lineOf(lines, "G1 Y#<y0> F600");
    const int across = lineOf(lines, "G1 X[#<x0> + #<width> * #<c> / #<cols>]");
    const int lift = lineOf(lines, "G0 Z1");
    const int endsub = lineOf(lines, "o<pocket> endsub");
    Expected e;
    e.moves << rapid(lineOf(lines, "G0 Z1", endsub), {}, {}, 1);
    struct Call
    {
        double x0, y0, width, height, depth;
    };
    for (const Call& c : {Call{10, 8, 6, 4, -2}, Call{22, 10, 5, 3, -1.5}}) {
        const int columns = int(std::ceil(c.width / 2));
        double z = 0;
        do {
            z = std::max(z - 1, c.depth);
            e.moves << rapid(over, c.x0, c.y0) << feed(down, {}, {}, z);
            for (int column = 0;; ++column) {
                e.moves << (column % 2 == 0 ? feed(up, {}, c.y0 + c.height) : feed(back, {}, c.y0));
                if (column + 1 > columns)
                    break;
                e.moves << feed(across, c.x0 + c.width * (column + 1) / columns, {});
            }
            e.moves << rapid(lift, {}, {}, 1);
        } while (z > c.depth);
    }
    e.moves << rapid(lineOf(lines, "G0 X10 Y8"), 10, 8);
    return e;
}

// engrave-params.ngc: N, Z, N of 1 x 2 units of 2.5 mm from (12, 20), half a unit apart,
// 0.4 mm deep.
inline Expected engraveParams(const QStringList& lines, double scale = 2.5)
{
    const int otherwise = lineOf(lines, "o20 else");
    const int nOver = lineOf(lines, "G0 X#<left> Y#<y0>");
    const int nDown = lineOf(lines, "G1 Z#<depth> F300");
    const int nUp = lineOf(lines, "G1 Y#<top> F600");
    const int nDiagonal = lineOf(lines, "G1 X#<right> Y#<y0>");
    const int nUpAgain = lineOf(lines, "G1 Y#<top>");
    const int zOver = lineOf(lines, "G0 X#<left> Y#<top>", otherwise);
    const int zDown = lineOf(lines, "G1 Z#<depth> F300", otherwise);
    const int zTop = lineOf(lines, "G1 X#<right> F600", otherwise);
    const int zDiagonal = lineOf(lines, "G1 X#<left> Y#<y0>", otherwise);
    const int zBottom = lineOf(lines, "G1 X#<right>", otherwise);
    Expected e;
    e.moves << rapid(lineOf(lines, "G0 Z1"), {}, {}, 1);
    for (int n = 0; n < 3; ++n) {
        const double left = 12 + n * 1.5 * scale;
        const double right = left + scale;
        const double bottom = 20;
        const double top = bottom + 2 * scale;
        const bool letterN = n % 2 == 0;
        e.messages << Message{
            lineOf(lines,
                   letterN ? "(PRINT, letter N at #<left>)" : "(PRINT, letter Z at #<left>)"),
            QStringLiteral("letter %1 at %2").arg(letterN ? 'N' : 'Z').arg(shown(left))};
        if (letterN)
            e.moves << rapid(nOver, left, bottom) << feed(nDown, {}, {}, -0.4) << feed(nUp, {}, top)
                    << feed(nDiagonal, right, bottom) << feed(nUpAgain, {}, top);
        else
            e.moves << rapid(zOver, left, top) << feed(zDown, {}, {}, -0.4) << feed(zTop, right, {})
                    << feed(zDiagonal, left, bottom) << feed(zBottom, right, {});
        e.moves << rapid(lineOf(lines, "G0 Z1", otherwise), {}, {}, 1);
    }
    e.moves << rapid(lineOf(lines, "G0 X#<x0> Y#<y0>"), 12, 20);
    return e;
}

inline Expected expectedOf(const QString& file, const QStringList& lines)
{
    if (file == QLatin1String("bolt-circle.ngc"))
        return boltCircle(lines);
    if (file == QLatin1String("pocket-sub.ngc"))
        return pocketSub(lines);
    return engraveParams(lines);
}

// Where the axes stand after each move, from `start` (work coordinates).
inline QList<Point> positionsAfter(const QList<Move>& moves, Point start)
{
    QList<Point> out;
    for (const Move& m : moves) {
        start.x = m.x.value_or(start.x);
        start.y = m.y.value_or(start.y);
        start.z = m.z.value_or(start.z);
        out << start;
    }
    return out;
}

// Every source line a move names was found in the file.
inline bool linesFound(const Expected& e)
{
    for (const Move& m : e.moves)
        if (m.line <= 0)
            return false;
    for (const Message& m : e.messages)
        if (m.line <= 0)
            return false;
    return true;
}

} // namespace stepdeck::program::ngctest
