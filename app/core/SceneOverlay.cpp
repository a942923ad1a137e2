// SPDX-License-Identifier: MIT
#include "SceneOverlay.hpp"

#include "BoxWidget.hpp"
#include "Measure.hpp"
#include "PlaneWidget.hpp"
#include "ProbeTable.hpp"
#include "StreamlineSeeds.hpp"

#include <QFontMetrics>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>

#include <glm/mat4x4.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace volpost::app {

namespace {

// Numbers shown next to markers: four significant digits, as the legend shows them.
QString shortNumber(double v) { return std::isfinite(v) ? QString::number(v, 'g', 5) : QString("no value"); }

// Labels placed so far in this picture: a new one moves down past any it would cover.
using PlacedLabels = std::vector<QRectF>;

// A label in a rounded box next to a marker, kept inside `area` and off the others.
void drawLabel(QPainter& painter, const QRect& area, QPointF at, const QString& text, const QColor& edge,
               PlacedLabels& placed) {
  const QFontMetrics fm(painter.font());
  QRectF box(at + QPointF(8, -fm.height() - 6), QSizeF(fm.horizontalAdvance(text) + 8, fm.height() + 4));
  if (box.right() > area.right() - 2) box.moveRight(at.x() - 8);
  if (box.top() < area.top() + 2) box.moveTop(at.y() + 8);
  for (int tries = 0; tries < 8; ++tries) {
    const auto covered = std::find_if(placed.begin(), placed.end(), [&](const QRectF& r) { return r.intersects(box); });
    if (covered == placed.end()) break;
    box.moveTop(covered->bottom() + 2);
  }
  placed.push_back(box);
  painter.setPen(QPen(edge, 1.0));
  painter.setBrush(QColor(255, 255, 255, 220));
  painter.drawRoundedRect(box, 3, 3);
  painter.setPen(QColor(20, 20, 20));
  painter.drawText(box, Qt::AlignCenter, text);
}

enum class MarkerShape { Dot, Up, Down, Node, Label };  // Label: its text only

struct Marker {
  QPointF at;
  QString text;  ///< empty: no label
  QColor color;
  MarkerShape shape = MarkerShape::Dot;
};

// `scale`: 1 for text of 12 px; markers grow with the text in large pictures.
// A node's or an element's number right beside it, dark on a light halo: hundreds of them
// stay where they belong (a boxed label would be pushed away from its point).
void drawNumber(QPainter& painter, const Marker& m) {
  QPainterPath path;
  path.addText(m.at + QPointF(3, -3), painter.font(), m.text);
  painter.save();
  painter.setBrush(Qt::NoBrush);
  painter.setPen(QPen(QColor(255, 255, 255, 220), 3.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
  painter.drawPath(path);
  painter.setPen(Qt::NoPen);
  painter.setBrush(m.color.darker(160));
  painter.drawPath(path);
  painter.restore();
}

void drawMarkerShape(QPainter& painter, const Marker& m, double scale) {
  painter.setPen(QPen(Qt::white, 1.5 * scale));
  painter.setBrush(m.color);
  if (m.shape == MarkerShape::Label) return;
  if (m.shape == MarkerShape::Node) {  // many of them: small, no outline
    painter.setPen(Qt::NoPen);
    painter.drawRect(QRectF(m.at - QPointF(2.5, 2.5) * scale, QSizeF(5, 5) * scale));
    return;
  }
  if (m.shape == MarkerShape::Dot) {
    painter.drawEllipse(m.at, 4.5 * scale, 4.5 * scale);
    return;
  }
  QPainterPath triangle;  // pointing up for a max, down for a min
  const double s = (m.shape == MarkerShape::Up ? -7.0 : 7.0) * scale;
  triangle.moveTo(m.at + QPointF(0, s));
  triangle.lineTo(m.at + QPointF(-6 * scale, -s * 0.6));
  triangle.lineTo(m.at + QPointF(6 * scale, -s * 0.6));
  triangle.closeSubpath();
  painter.drawPath(triangle);
}

// A marker on the side a clip plane (or the box) removed is not drawn: the model is not
// there to carry it. What lies on a plane stays, within a rounding of the model's size.
bool keptByClipPlanes(const Scene& scene, const glm::dvec3& p) {
  const double tolerance = 1e-9 * std::max(scene.session()->bounds().diagonal(), 1e-300);
  for (const ClipPlane& c : scene.volume().allClipPlanes()) {
    const double length = glm::length(c.normal);
    if (length > 0.0 && glm::dot(c.normal / length, p - c.point) < -tolerance) return false;
  }
  return true;
}

void addProbes(std::vector<Marker>& markers, const QRect& area, const Scene& scene) {
  const auto& probes = scene.probes();
  if (probes.empty() || !scene.session()) return;
  const bool labels = probes.size() <= 50;  // more would hide the model
  const Camera camera = scene.pictureCamera(area.width(), area.height());
  for (std::size_t i = 0; i < probes.size(); ++i) {
    if (!keptByClipPlanes(scene, probes[i])) continue;
    const auto at = camera.projectToPicture(probes[i], area.width(), area.height());
    if (!at) continue;
    Marker m{QPointF(area.left() + at->x, area.top() + at->y), {}, QColor(20, 90, 200), MarkerShape::Dot};
    if (labels) {
      m.text = QString("%1").arg(i + 1);
      if (scene.view()) {
        const auto& v = scene.probedValues()[i];
        m.text += v ? QString(": %1").arg(shortNumber(*v)) : QString(": outside");
      }
    }
    markers.push_back(m);
  }
}

// The marked set's nodes, small magenta squares (a color no result map uses), the set's
// name beside the first.
void addMarkedSet(std::vector<Marker>& markers, const QRect& area, const Scene& scene) {
  const Scene::MarkedSet& set = scene.markedSet();
  if (set.nodes.empty()) return;
  const Camera camera = scene.pictureCamera(area.width(), area.height());
  const QColor magenta(220, 0, 200);
  const auto place = [&](const glm::dvec3& p, const QString& text, MarkerShape shape) {
    if (!keptByClipPlanes(scene, p)) return false;
    const auto at = camera.projectToPicture(p, area.width(), area.height());
    if (!at) return false;
    markers.push_back({QPointF(area.left() + at->x, area.top() + at->y), text, magenta, shape});
    return true;
  };
  // The set's name beside its first node, unless numbers are written (they say more).
  bool named = !set.numbers.empty();
  for (const glm::dvec3& p : set.nodes)
    if (place(p, named ? QString() : QString::fromStdString(scene.setVisibility().marked), MarkerShape::Node))
      named = true;
  for (const Scene::MarkedSet::Number& n : set.numbers) place(n.at, QString::number(n.id), MarkerShape::Label);
}

void addExtremes(std::vector<Marker>& markers, const QRect& area, const Scene& scene) {
  if (!scene.marksExtremes()) return;
  const auto e = scene.extremes();
  if (!e) return;
  const Camera camera = scene.pictureCamera(area.width(), area.height());
  const auto add = [&](const glm::dvec3& where, const QString& text, const QColor& color, MarkerShape shape) {
    if (!keptByClipPlanes(scene, where)) return;
    if (const auto at = camera.projectToPicture(where, area.width(), area.height()))
      markers.push_back({QPointF(area.left() + at->x, area.top() + at->y), text, color, shape});
  };
  add(e->maxAt, QString("max %1").arg(shortNumber(e->max)), QColor(200, 30, 30), MarkerShape::Up);
  add(e->minAt, QString("min %1").arg(shortNumber(e->min)), QColor(30, 60, 200), MarkerShape::Down);
}

// The model's axes as the camera sees them, in the lower left corner: x red, y green, z
// blue, the ones pointing away drawn first (behind).
void paintTriad(QPainter& painter, const QRect& area, const Camera& camera, double scale) {
  const glm::dvec3 right = glm::cross(camera.viewDirection(), camera.up());
  const double length = 26.0 * scale;
  const QPointF centre(area.left() + 14.0 * scale + length, area.bottom() - 14.0 * scale - length);
  struct Axis {
    glm::dvec3 direction;
    QColor color;
    const char* name;
  };
  std::array<Axis, 3> axes{{{{1, 0, 0}, QColor(210, 40, 40), "x"},
                            {{0, 1, 0}, QColor(40, 160, 40), "y"},
                            {{0, 0, 1}, QColor(40, 80, 220), "z"}}};
  std::sort(axes.begin(), axes.end(), [&](const Axis& a, const Axis& b) {
    return glm::dot(a.direction, camera.viewDirection()) > glm::dot(b.direction, camera.viewDirection());
  });
  const QFontMetricsF fm(painter.font());
  for (const Axis& a : axes) {
    const QPointF tip = centre + QPointF(glm::dot(a.direction, right), -glm::dot(a.direction, camera.up())) * length;
    painter.setPen(QPen(a.color, 2.0 * scale, Qt::SolidLine, Qt::RoundCap));
    painter.drawLine(centre, tip);
    const QPointF away = tip - centre;
    const double n = std::hypot(away.x(), away.y());
    const QPointF at = tip + (n > 1e-6 ? away / n : QPointF(0, 0)) * 7.0 * scale;
    const QSizeF size(fm.horizontalAdvance(a.name), fm.height());
    painter.drawText(QRectF(at - QPointF(size.width(), size.height()) / 2.0, size), Qt::AlignCenter, a.name);
  }
}

// Where a model point lands in `area` (nullopt behind the eye): the widgets' projection.
struct PointInArea {
  Camera camera;
  QRect area;
  std::optional<QPointF> operator()(const glm::dvec3& p) const;
};

// A clip plane's widget: its outline in the model's box and the normal handle (shaft and
// knob) that the window's mouse drags. Every free plane has one.
void paintPlaneWidget(QPainter& painter, const QRect& area, const Scene& scene, const ClipPlane& plane, double scale) {
  const PlaneWidget widget = planeWidget(plane, scene.session()->bounds());
  const PointInArea at{scene.pictureCamera(area.width(), area.height()), area};
  const QColor color(250, 170, 20);
  QPolygonF outline;
  for (const glm::dvec3& p : widget.outline)
    if (const auto q = at(p)) outline << *q;
  if (outline.size() >= 3) {  // an outline only: a fill washed out the cut face's colors under it
    painter.setPen(QPen(color, 1.5 * scale));
    painter.setBrush(Qt::NoBrush);
    painter.drawPolygon(outline);
  }
  const auto center = at(widget.center), knob = at(widget.knob);
  if (!center || !knob) return;
  painter.setPen(QPen(color, 2.5 * scale, Qt::SolidLine, Qt::RoundCap));
  painter.drawLine(*center, *knob);
  painter.setPen(QPen(Qt::white, 1.5 * scale));
  painter.setBrush(color);
  painter.drawEllipse(*knob, 6.0 * scale, 6.0 * scale);
}

// The clip box's edges and a knob on each face, as the window drags them.
void paintBoxWidget(QPainter& painter, const QRect& area, const Scene& scene, double scale) {
  const BoxWidget widget = boxWidget(*scene.shownClipBox());
  const PointInArea at{scene.pictureCamera(area.width(), area.height()), area};
  const QColor color(40, 150, 240);
  painter.setPen(QPen(color, 1.5 * scale));
  for (const auto& e : boxEdges()) {
    const auto a = at(widget.corners[std::size_t(e[0])]), b = at(widget.corners[std::size_t(e[1])]);
    if (a && b) painter.drawLine(*a, *b);
  }
  painter.setPen(QPen(Qt::white, 1.5 * scale));
  painter.setBrush(color);
  // Square knobs: the round dots are probed points.
  for (const glm::dvec3& c : widget.faceCenters)
    if (const auto q = at(c)) painter.drawRect(QRectF(*q - QPointF(5.0, 5.0) * scale, QSizeF(10.0, 10.0) * scale));
}

// The Plot Over Line panel's line: dashed, its ends marked A and B as the chart's axis runs.
void paintPlotLine(QPainter& painter, const QRect& area, const Scene& scene, const std::array<glm::dvec3, 2>& line,
                   double scale) {
  const PointInArea at{scene.pictureCamera(area.width(), area.height()), area};
  const auto a = at(line[0]), b = at(line[1]);
  if (!a || !b) return;
  const QColor color(120, 40, 160);
  painter.setPen(QPen(color, 2.0 * scale, Qt::DashLine, Qt::RoundCap));
  painter.drawLine(*a, *b);
  painter.setPen(QPen(Qt::white, 1.0 * scale));
  painter.setBrush(color);
  const QFontMetricsF fm(painter.font());
  for (const auto& [p, name] : {std::pair{*a, "A"}, std::pair{*b, "B"}}) {
    const double r = 0.5 * fm.height() + 2.0;
    painter.drawEllipse(p, r, r);
    painter.drawText(QRectF(p - QPointF(r, r), QSizeF(2 * r, 2 * r)), Qt::AlignCenter, name);
  }
}

// The element the hover names, its edges drawn over the picture (through the midside
// nodes of a quadratic one), and its node ringed.
void paintHighlight(QPainter& painter, const QRect& area, const Scene& scene, double scale) {
  const auto h = scene.highlight();
  if (!h || !scene.session()) return;
  const Model& model = scene.session()->model();
  const PointInArea at{scene.pictureCamera(area.width(), area.height()), area};
  const auto nodes = model.mesh().cellNodes(h->cell);
  const CellTopology& t = topology(model.mesh().cellType(h->cell));
  const QColor color(255, 200, 0);
  for (const int pass : {0, 1}) {  // a dark edge under a light one: seen on any color
    painter.setPen(pass == 0 ? QPen(QColor(40, 40, 40), 4.0 * scale, Qt::SolidLine, Qt::RoundCap)
                             : QPen(color, 2.0 * scale, Qt::SolidLine, Qt::RoundCap));
    for (const CellEdge& e : t.edges) {
      QPolygonF edge;
      for (const int local : {int(e.a), int(e.mid), int(e.b)}) {
        if (local < 0) continue;
        if (const auto p = at(model.nodePosition(nodes[std::size_t(local)]))) edge << *p;
      }
      if (edge.size() >= 2) painter.drawPolyline(edge);
    }
  }
  if (h->node)
    if (const auto p = at(model.nodePosition(*h->node))) {
      painter.setPen(QPen(QColor(40, 40, 40), 2.0 * scale));
      painter.setBrush(color);
      painter.drawEllipse(*p, 4.0 * scale, 4.0 * scale);
    }
}

// A measure between probes: the segments drawn, each distance written at its middle, and
// with three probes the angle at the second written at its corner.
void paintMeasure(QPainter& painter, const QRect& area, const Scene& scene, double scale, PlacedLabels& placed) {
  const auto& measure = scene.measure();
  const auto& probes = scene.probes();
  if (measure.size() < 2) return;
  const PointInArea at{scene.pictureCamera(area.width(), area.height()), area};
  std::vector<glm::dvec3> points;
  std::vector<std::optional<QPointF>> drawn;
  for (const std::size_t i : measure) {
    if (i >= probes.size()) return;
    points.push_back(probes[i]);
    drawn.push_back(at(probes[i]));
  }
  const QColor color(20, 20, 20);
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    if (!drawn[k] || !drawn[k + 1]) continue;
    painter.setPen(QPen(Qt::white, 4.0 * scale, Qt::SolidLine, Qt::RoundCap));
    painter.drawLine(*drawn[k], *drawn[k + 1]);
    painter.setPen(QPen(color, 1.6 * scale, Qt::SolidLine, Qt::RoundCap));
    painter.drawLine(*drawn[k], *drawn[k + 1]);
    drawLabel(painter, area, (*drawn[k] + *drawn[k + 1]) / 2.0,
              QString::fromStdString(displayNumber(distanceBetween(points[k], points[k + 1]))), color, placed);
  }
  if (points.size() == 3 && drawn[1]) {
    const auto angle = angleAt(points[0], points[1], points[2]);
    if (angle)
      drawLabel(painter, area, *drawn[1], QString::fromStdString(displayNumber(*angle)) + QChar(0x00B0), color, placed);
  }
}

// The streamlines' seeds where they are (a placed rake's points, line seeds), so they can be
// seen, edited in the Streamlines dialog and placed anew.
void paintRakes(QPainter& painter, const QRect& area, const Scene& scene, double scale) {
  const PointInArea at{scene.pictureCamera(area.width(), area.height()), area};
  const QColor color(230, 120, 20);
  // Point seeds as dots joined in their order (a rake placed with the mouse), line seeds as lines.
  std::optional<QPointF> previous;
  for (const std::string& spec : scene.streamlines().seeds) {
    if (const auto seed = pointSeed(spec)) {
      const auto p = at(*seed);
      if (!p) continue;
      if (previous) {
        painter.setPen(QPen(color, 1.0 * scale, Qt::DotLine));
        painter.drawLine(*previous, *p);
      }
      painter.setBrush(color);
      painter.setPen(QPen(Qt::white, 1.0 * scale));
      painter.drawEllipse(*p, 3.0 * scale, 3.0 * scale);
      previous = p;
      continue;
    }
    previous.reset();
    const auto ends = rakeEnds(spec);
    if (!ends) continue;
    const auto a = at((*ends)[0]), b = at((*ends)[1]);
    if (!a || !b) continue;
    painter.setPen(QPen(color, 2.0 * scale, Qt::SolidLine, Qt::RoundCap));
    painter.drawLine(*a, *b);
    painter.setBrush(color);
    painter.setPen(QPen(Qt::white, 1.0 * scale));
    painter.drawEllipse(*a, 4.0 * scale, 4.0 * scale);
    painter.drawEllipse(*b, 4.0 * scale, 4.0 * scale);
  }
}

std::optional<QPointF> PointInArea::operator()(const glm::dvec3& p) const {
  const auto q = camera.projectToPicture(p, area.width(), area.height());
  if (!q) return std::nullopt;
  return QPointF(area.left() + q->x, area.top() + q->y);
}

// The picture's caption at the top left: the state's title, then what a report must say
// about the picture: the deformation's factor when the shape is drawn deformed.
void paintCaption(QPainter& painter, const QRect& room, const Scene& scene) {
  QStringList lines;
  if (!scene.shown().title.empty()) lines << QString::fromStdString(scene.shown().title);
  if (scene.shown().stepText && scene.view())
    lines << QString("%1, %2").arg(QString::fromStdString(scene.view()->quantity.displayName()),
                                   QString::fromStdString(scene.view()->stepLabel));
  if (scene.deformation().shown && scene.deformationScale() != 0.0)
    lines << QString("Deformed shape: %1 x %2")
                 .arg(QString::fromStdString(scene.deformation().field))
                 .arg(scene.deformationScale(), 0, 'g', 4);
  if (lines.isEmpty()) return;
  painter.save();
  const QFont font = painter.font();
  int y = room.top() + 6;
  for (int i = 0; i < lines.size(); ++i) {
    QFont lineFont = font;
    if (i == 0 && !scene.shown().title.empty()) {
      lineFont.setPixelSize(int(font.pixelSize() * 1.4));
      lineFont.setBold(true);
    }
    painter.setFont(lineFont);
    const QFontMetrics fm(lineFont);
    painter.setPen(textColorOver(isDarkBackground(scene.shown().background)));
    painter.drawText(QRect(room.left() + 8, y, room.width() - 16, fm.height()), Qt::AlignLeft | Qt::AlignVCenter,
                     fm.elidedText(lines[i], Qt::ElideRight, room.width() - 16));
    y += fm.height() + 2;
  }
  painter.restore();
}

}  // namespace

void paintSceneOverlay(QPainter& painter, const QRect& area, const Scene& scene) {
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing);
  QFont font = painter.font();
  // A little smaller than the legend, as much larger as the state's text scale asks.
  font.setPixelSize(std::max(6, int(std::lround(std::clamp(area.height() / 54, 9, 84) * scene.shown().textScale))));
  painter.setFont(font);
  const double scale = std::max(1.0, font.pixelSize() / 12.0);
  if (scene.showsPlaneWidget())
    for (const ClipPlane& plane : scene.volume().clipPlanes) paintPlaneWidget(painter, area, scene, plane, scale);
  if (scene.showsBoxWidget()) paintBoxWidget(painter, area, scene, scale);
  if (const auto& line = scene.plotLine()) paintPlotLine(painter, area, scene, *line, scale);
  if (scene.showsRakes()) paintRakes(painter, area, scene, scale);
  std::vector<Marker> markers;
  addMarkedSet(markers, area, scene);  // first: the extremes and probes are drawn over them
  addExtremes(markers, area, scene);
  addProbes(markers, area, scene);
  PlacedLabels placed;  // the markers first: no label covers one
  for (const Marker& m : markers) placed.push_back(QRectF(m.at - QPointF(7, 7) * scale, QSizeF(14, 14) * scale));
  for (const Marker& m : markers) drawMarkerShape(painter, m, scale);
  QRect room = area;  // labels stay left of the legend's strip
  const std::vector<LegendPicture> legends = scene.legends();
  if (!legends.empty())
    room.setRight(std::max(area.left() + area.width() / 2, area.right() - legendWidth(area, legends.front().content)));
  paintHighlight(painter, area, scene, scale);
  paintMeasure(painter, area, scene, scale, placed);
  for (const Marker& m : markers) {
    if (m.text.isEmpty()) continue;
    if (m.shape == MarkerShape::Label) drawNumber(painter, m);
    else drawLabel(painter, room, m.at, m.text, m.color, placed);
  }
  if (scene.showsTriad()) paintTriad(painter, area, scene.camera(), scale);
  paintCaption(painter, room, scene);
  painter.restore();
  // Several keys share the strip, one above the other.
  for (std::size_t i = 0; i < legends.size(); ++i) {
    const int top = area.top() + int(i) * area.height() / int(legends.size());
    const int bottom = area.top() + int(i + 1) * area.height() / int(legends.size());
    paintLegend(painter, QRect(area.left(), top, area.width(), bottom - top), legends[i].colors, legends[i].content);
  }
}

}  // namespace volpost::app
