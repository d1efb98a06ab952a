// SPDX-License-Identifier: GPL-3.0-or-later
#include "Fillets/CentreLine.h"

#include "Fillets/CircleFit.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace medialaxis
{
LineEnd FitLineEnd(const std::vector<Point3>& centres, const std::vector<double>& radii, bool back)
{
  const std::size_t n = centres.size();
  auto vertex = [&](std::size_t k) { return back ? n - 1 - k : k; };
  const double endRadius = radii[vertex(0)];
  std::vector<double> arc{ 0.0 };
  while (arc.size() < n && (arc.size() < 3 || arc.back() <= 3.0 * endRadius))
  {
    const std::size_t k = arc.size();
    arc.push_back(arc.back() + Norm(centres[vertex(k)] - centres[vertex(k - 1)]));
  }
  const double count = static_cast<double>(arc.size());
  double sMean = 0.0, rMean = 0.0;
  Point3 cMean{ 0.0, 0.0, 0.0 };
  for (std::size_t k = 0; k < arc.size(); ++k)
  {
    sMean += arc[k] / count;
    rMean += radii[vertex(k)] / count;
    cMean = cMean + (1.0 / count) * centres[vertex(k)];
  }
  double sVariance = 0.0, rCovariance = 0.0;
  Point3 cCovariance{ 0.0, 0.0, 0.0 };
  for (std::size_t k = 0; k < arc.size(); ++k)
  {
    const double ds = arc[k] - sMean;
    sVariance += ds * ds;
    rCovariance += ds * (radii[vertex(k)] - rMean);
    cCovariance = cCovariance + ds * (centres[vertex(k)] - cMean);
  }
  LineEnd end;
  if (!(sVariance > 0.0))
  {
    return end;
  }
  const Point3 inwards = (1.0 / sVariance) * cCovariance; // d centre / d arc
  const double speed = Norm(inwards);
  if (!(speed > 0.0))
  {
    return end;
  }
  end.Valid = true;
  end.Centre = cMean - sMean * inwards;
  end.Radius =
    std::clamp(rMean - sMean * rCovariance / sVariance, 0.5 * endRadius, 1.5 * endRadius);
  end.Direction = (-1.0 / speed) * inwards;
  end.Slope = std::clamp(-rCovariance / sVariance / speed, -0.45, 0.45);
  return end;
}

namespace
{
// The point of a polyline nearest to p (closed: the last vertex joins the
// first): on segment Segment (vertex Segment to the next), at Along in
// [0, 1] (Unclamped before clamping), the first such in case of ties.
struct PolylineFoot
{
  std::size_t Segment = 0;
  double Along = 0.0, Unclamped = 0.0;
  Point3 Foot;
};

// The vertex one step (+1 or -1) from k on a closed line of n vertices.
std::size_t StepAlong(std::size_t k, int step, std::size_t n)
{
  return step > 0 ? (k + 1) % n : (k + n - 1) % n;
}

PolylineFoot NearestOnPolyline(const std::vector<Point3>& line, bool closed, const Point3& p)
{
  const std::size_t n = line.size();
  const std::size_t segments = closed ? n : (n > 0 ? n - 1 : 0);
  PolylineFoot nearest;
  nearest.Foot = n > 0 ? line[0] : p;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < segments; ++i)
  {
    const Point3 &a = line[i], &b = line[(i + 1) % n];
    const Point3 ab = b - a;
    const double length2 = Dot(ab, ab);
    const double u = length2 > 0.0 ? Dot(p - a, ab) / length2 : 0.0;
    const double along = std::clamp(u, 0.0, 1.0);
    const Point3 q = a + along * ab;
    const double d = Norm(p - q);
    if (d < best)
    {
      best = d;
      nearest = { i, along, u, q };
    }
  }
  return nearest;
}
}

void RefineCentreLine(
  Fillet& fillet, const std::vector<Point3>& points, double inlier, bool fromLine)
{
  const std::size_t n = fillet.Centres.size();
  std::vector<Point3> centres = fillet.Centres;
  const std::vector<double> radii0 = fillet.Radii;
  std::vector<std::uint8_t> fitted(n, 0);
  std::vector<double> arc(n, 0.0);
  // Each point goes to the vertex nearest to its closest point on the line.
  std::vector<std::vector<Point3>> nearest(n);
  for (const Point3& p : points)
  {
    const PolylineFoot nearestPoint = NearestOnPolyline(centres, fillet.Closed, p);
    const std::size_t bestVertex =
      nearestPoint.Along < 0.5 ? nearestPoint.Segment : (nearestPoint.Segment + 1) % n;
    // Stored relative to the vertex, or to the foot moved to the vertex.
    nearest[bestVertex].push_back(fromLine ? centres[bestVertex] + (p - nearestPoint.Foot) : p);
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    // Tangent over about one radius on each side: short medial edges zig-zag.
    std::size_t previous = i, next = i;
    for (std::size_t k = 1; k < n; ++k)
    {
      if (!fillet.Closed && k > i)
      {
        break;
      }
      previous = (i + n - k) % n;
      if (Norm(centres[previous] - centres[i]) >= fillet.Radii[i])
      {
        break;
      }
    }
    for (std::size_t k = 1; k < n; ++k)
    {
      if (!fillet.Closed && i + k >= n)
      {
        break;
      }
      next = (i + k) % n;
      if (Norm(centres[next] - centres[i]) >= fillet.Radii[i])
      {
        break;
      }
    }
    const Point3 tangent = Normalized(centres[next] - centres[previous]);
    if (nearest[i].size() < 6 || Norm(tangent) == 0.0)
    {
      continue;
    }
    // A frame across the line.
    const Point3 helper = std::abs(tangent[0]) < 0.9 ? Point3{ 1, 0, 0 } : Point3{ 0, 1, 0 };
    const Point3 e1 = Normalized(Cross(tangent, helper)), e2 = Cross(tangent, e1);
    // A thin slice across the line: the points nearest to the vertex's plane
    // (at most a quarter radius away). Farther along, the curvature of the
    // line, an error of the tangent or a changing radius would smear the
    // section.
    std::vector<std::pair<double, Point3>> slice;
    for (const Point3& p : nearest[i])
    {
      const Point3 d = p - centres[i];
      const double s = Dot(d, tangent);
      if (std::abs(s) <= 0.25 * fillet.Radii[i])
      {
        slice.push_back({ s, d });
      }
    }
    constexpr std::size_t SlicePoints = 24;
    if (slice.size() > SlicePoints)
    {
      std::nth_element(slice.begin(), slice.begin() + SlicePoints, slice.end(),
        [](const auto& a, const auto& b)
        {
          return std::abs(a.first) < std::abs(b.first) ||
            (std::abs(a.first) == std::abs(b.first) && a.first < b.first);
        });
      slice.resize(SlicePoints);
    }
    std::vector<std::array<double, 2>> section;
    double along = 0.0;
    for (const auto& [s, d] : slice)
    {
      section.push_back({ Dot(d, e1), Dot(d, e2) });
      along += s;
    }
    // The section lies where its points are along the line (interior
    // vertices; the ends keep the line's extent).
    const bool end = !fillet.Closed && (i == 0 || i + 1 == n);
    along = slice.empty() || end ? 0.0 : along / static_cast<double>(slice.size());
    const FittedCircle circle = FitCircleRobust(section, inlier);
    const double r = fillet.Radii[i];
    // Junctions (corner balls, several fillets) have no single section.
    if (circle.Valid && circle.InlierFraction >= 0.5 && std::hypot(circle.X, circle.Y) < 0.5 * r &&
      std::abs(circle.Radius - r) < 0.5 * r)
    {
      fillet.Centres[i] = centres[i] + circle.X * e1 + circle.Y * e2 + along * tangent;
      fillet.Radii[i] = circle.Radius;
      fitted[i] = 1;
      arc[i] = circle.InlierArc;
    }
  }
  // A section that sees only part of the arc pins its centre poorly (a
  // shorter arc of the same radius fits with the centre slid along it):
  // it must span most of what the line's sections typically span.
  std::vector<double> arcs;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (fitted[i])
    {
      arcs.push_back(arc[i]);
    }
  }
  if (!arcs.empty())
  {
    std::nth_element(arcs.begin(), arcs.begin() + arcs.size() / 2, arcs.end());
    const double typical = arcs[arcs.size() / 2];
    for (std::size_t i = 0; i < n; ++i)
    {
      if (fitted[i] && arc[i] < 0.75 * typical)
      {
        fitted[i] = 0;
        fillet.Centres[i] = centres[i];
        fillet.Radii[i] = radii0[i];
      }
    }
  }
  // A fit whose radius stands out from its neighbours' trend (an odd
  // section, e.g. where fins cross the line) does not count. The trend is
  // linear along the line, robustly: the median slope of the pairs of fits
  // around, and the median of what each neighbour predicts with it (a
  // variable-radius fillet's radius changes from one section to the next).
  auto median = [](std::vector<double> values)
  {
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
  };
  std::vector<std::uint8_t> trusted = fitted;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!fitted[i])
    {
      continue;
    }
    // Fitted vertices within two steps, with their signed distance along.
    std::vector<std::pair<double, std::size_t>> window{ { 0.0, i } };
    for (int step = -1; step <= 1; step += 2)
    {
      std::size_t k = i;
      double along = 0.0;
      for (int count = 0; count < 2; ++count)
      {
        if (!fillet.Closed && ((step < 0 && k == 0) || (step > 0 && k + 1 == n)))
        {
          break;
        }
        const std::size_t next = StepAlong(k, step, n);
        along += Norm(centres[next] - centres[k]);
        k = next;
        if (k == i ||
          std::any_of(
            window.begin(), window.end(), [&](const auto& entry) { return entry.second == k; }))
        {
          break;
        }
        if (fitted[k])
        {
          window.push_back({ step * along, k });
        }
      }
    }
    if (window.size() < 3)
    {
      continue;
    }
    std::vector<double> slopes, predictions;
    for (std::size_t a = 0; a < window.size(); ++a)
    {
      for (std::size_t b = a + 1; b < window.size(); ++b)
      {
        const double ds = window[b].first - window[a].first;
        if (ds != 0.0)
        {
          slopes.push_back((fillet.Radii[window[b].second] - fillet.Radii[window[a].second]) / ds);
        }
      }
    }
    const double slope = slopes.empty() ? 0.0 : median(slopes);
    for (std::size_t a = 1; a < window.size(); ++a)
    {
      predictions.push_back(fillet.Radii[window[a].second] - slope * window[a].first);
    }
    const double predicted = median(predictions);
    trusted[i] = std::abs(fillet.Radii[i] - predicted) <= 4.0 * inlier * predicted;
  }
  // Vertices without a trusted fit take the radius of the trusted ones on
  // both sides, weighted by distance along the line, and a centre on the
  // cubic (Hermite) curve through those fits with the tangents their own
  // neighbouring fits give: a chord would cut across a curved line, and
  // the raw medial vertex zig-zags about it.
  std::vector<Point3> offset(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    offset[i] = fillet.Centres[i] - centres[i];
  }
  const std::vector<double> radii = fillet.Radii;
  // The nearest trusted vertex from j in direction step (+1 or -1), -1 for
  // none, and the distance to it along the line.
  auto nearestTrusted = [&](std::size_t j, int step, double& distance) -> long
  {
    distance = 0.0;
    std::size_t k = j;
    for (std::size_t count = 1; count < n; ++count)
    {
      if (!fillet.Closed && ((step < 0 && k == 0) || (step > 0 && k + 1 == n)))
      {
        return -1;
      }
      const std::size_t next = StepAlong(k, step, n);
      distance += Norm(centres[next] - centres[k]);
      k = next;
      if (trusted[k])
      {
        return static_cast<long>(k);
      }
    }
    return -1;
  };
  auto fit = [&](std::size_t j) { return centres[j] + offset[j]; };
  for (std::size_t i = 0; i < n; ++i)
  {
    if (trusted[i])
    {
      continue;
    }
    double toBefore = 0.0, toAfter = 0.0;
    const long before = nearestTrusted(i, -1, toBefore);
    const long after = nearestTrusted(i, +1, toAfter);
    if (before < 0 && after < 0)
    {
      fillet.Centres[i] = centres[i];
      continue;
    }
    if (!fillet.Closed && (before < 0 || after < 0))
    {
      // Past the last trusted fit towards an end of the line: continue the
      // trend of the last two (a radius changing along the line keeps
      // changing), or copy the last one when there is no second.
      const long first = before < 0 ? after : before;
      double between = 0.0;
      const long second =
        nearestTrusted(static_cast<std::size_t>(first), before < 0 ? 1 : -1, between);
      const double distance = before < 0 ? toAfter : toBefore;
      // At most as far again as the two fits are apart, and the radius
      // within half and one and a half times the last fit's.
      const double u = second >= 0 && between > 0.0 ? std::min(distance / between, 1.0) : 0.0;
      const std::size_t f = static_cast<std::size_t>(first);
      const std::size_t g = static_cast<std::size_t>(second >= 0 ? second : first);
      fillet.Centres[i] = second >= 0 ? fit(f) + u * (fit(f) - fit(g)) : centres[i] + offset[f];
      fillet.Radii[i] =
        std::clamp(radii[f] + u * (radii[f] - radii[g]), 0.5 * radii[f], 1.5 * radii[f]);
      continue;
    }
    const std::size_t b = static_cast<std::size_t>(before), a = static_cast<std::size_t>(after);
    const double span = toBefore + toAfter;
    const double w = toBefore / span;
    fillet.Radii[i] = (1.0 - w) * radii[b] + w * radii[a];
    if (a == b)
    {
      fillet.Centres[i] = centres[i] + offset[b];
      continue;
    }
    // Tangents (per unit length along the line) at the two fits.
    double beyondB = 0.0, beyondA = 0.0;
    const long bb = nearestTrusted(b, -1, beyondB), aa = nearestTrusted(a, +1, beyondA);
    const Point3 chord = (1.0 / span) * (fit(a) - fit(b));
    const Point3 tangentB = bb >= 0 && bb != static_cast<long>(a)
      ? (1.0 / (span + beyondB)) * (fit(a) - fit(static_cast<std::size_t>(bb)))
      : chord;
    const Point3 tangentA = aa >= 0 && aa != static_cast<long>(b)
      ? (1.0 / (span + beyondA)) * (fit(static_cast<std::size_t>(aa)) - fit(b))
      : chord;
    const double w2 = w * w, w3 = w2 * w;
    fillet.Centres[i] = (2 * w3 - 3 * w2 + 1) * fit(b) + ((w3 - 2 * w2 + w) * span) * tangentB +
      (3 * w2 - 2 * w3) * fit(a) + ((w3 - w2) * span) * tangentA;
  }
  // Where the radius changes along the line (slope r' = dr/ds), a ball
  // touches the fillet along a circle that is not its great circle: radius
  // r sqrt(1 - r'^2), centre r r' behind the ball's centre along the line.
  // The fits found those circles; turn them into balls.
  const std::vector<Point3> circleCentres = fillet.Centres;
  const std::vector<double> circleRadii = fillet.Radii;
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::size_t before = fillet.Closed ? (i + n - 1) % n : (i > 0 ? i - 1 : i);
    const std::size_t after = fillet.Closed ? (i + 1) % n : (i + 1 < n ? i + 1 : i);
    const Point3 step = circleCentres[after] - circleCentres[before];
    const double length = Norm(step);
    if (length == 0.0)
    {
      continue;
    }
    const double slope = std::clamp((circleRadii[after] - circleRadii[before]) / length, -0.9, 0.9);
    const double r = circleRadii[i] / std::sqrt(1.0 - slope * slope);
    fillet.Radii[i] = r;
    fillet.Centres[i] = circleCentres[i] + (slope * r / length) * step;
  }
}

double FacesArc(const Fillet& fillet, const std::vector<Point3>& points)
{
  const std::size_t n = fillet.Centres.size();
  if (n < 2)
  {
    return 0.0;
  }
  // Sections per segment of the line, each in the segment's own frame.
  std::vector<std::vector<std::array<double, 2>>> sections(fillet.Closed ? n : n - 1);
  for (const Point3& p : points)
  {
    const PolylineFoot foot = NearestOnPolyline(fillet.Centres, fillet.Closed, p);
    // Past an open line's ends the faces curve round its end ball.
    if (!fillet.Closed && (foot.Unclamped < 0.0 || foot.Unclamped > 1.0))
    {
      continue;
    }
    const std::size_t i = foot.Segment;
    const Point3 tangent = Normalized(fillet.Centres[(i + 1) % n] - fillet.Centres[i]);
    if (!(Norm(tangent) > 0.0))
    {
      continue;
    }
    const Point3 helper = std::abs(tangent[0]) < 0.9 ? Point3{ 1, 0, 0 } : Point3{ 0, 1, 0 };
    const Point3 e1 = Normalized(Cross(tangent, helper)), e2 = Cross(tangent, e1);
    const Point3 d = p - foot.Foot;
    sections[i].push_back({ Dot(d, e1), Dot(d, e2) });
  }
  std::vector<double> arcs;
  for (const auto& section : sections)
  {
    if (section.size() >= 6)
    {
      arcs.push_back(SpannedArc(section, 0.0, 0.0));
    }
  }
  if (arcs.empty())
  {
    return 0.0;
  }
  std::nth_element(arcs.begin(), arcs.begin() + arcs.size() / 2, arcs.end());
  return arcs[arcs.size() / 2];
}

void TrimFoldedEnds(Fillet& chain)
{
  if (chain.Closed)
  {
    return;
  }
  auto folds = [&chain](std::size_t a, std::size_t b, std::size_t c)
  { return Dot(chain.Centres[c] - chain.Centres[b], chain.Centres[b] - chain.Centres[a]) < 0.0; };
  while (chain.Vertices.size() >= 3 &&
    folds(chain.Vertices.size() - 3, chain.Vertices.size() - 2, chain.Vertices.size() - 1))
  {
    chain.Vertices.pop_back();
    chain.Centres.pop_back();
    chain.Radii.pop_back();
  }
  while (chain.Vertices.size() >= 3 && folds(2, 1, 0))
  {
    chain.Vertices.erase(chain.Vertices.begin());
    chain.Centres.erase(chain.Centres.begin());
    chain.Radii.erase(chain.Radii.begin());
  }
}

bool PastAnEnd(const std::vector<Point3>& line, const Point3& p)
{
  const PolylineFoot nearest = NearestOnPolyline(line, false, p);
  return (nearest.Segment == 0 && nearest.Unclamped < 0.0) ||
    (nearest.Segment + 2 == line.size() && nearest.Unclamped > 1.0);
}

void MeasureFillet(Fillet& chain)
{
  const std::size_t n = chain.Centres.size();
  const std::size_t segments = chain.Closed ? n : n - 1;
  double weighted = 0.0;
  chain.Length = 0.0;
  chain.MinimumRadius = *std::min_element(chain.Radii.begin(), chain.Radii.end());
  chain.MaximumRadius = *std::max_element(chain.Radii.begin(), chain.Radii.end());
  for (std::size_t i = 0; i < segments; ++i)
  {
    const std::size_t j = (i + 1) % n;
    const double length = Norm(chain.Centres[j] - chain.Centres[i]);
    chain.Length += length;
    weighted += 0.5 * length * (chain.Radii[i] + chain.Radii[j]);
  }
  chain.MeanRadius = chain.Length > 0.0 ? weighted / chain.Length : chain.MaximumRadius;
  chain.RadiusVariation =
    chain.MeanRadius > 0.0 ? (chain.MaximumRadius - chain.MinimumRadius) / chain.MeanRadius : 0.0;
}
}
