"""Finding the balls in the simulated camera's images: an example detector, in OpenCV and NumPy.

It does what a simple vision pipeline over a pool table does: it learns the cloth's colour
from the image, marks everything that differs from it on the cloth, finds ball centres as the
peaks of that mask's distance transform (a ball is a disc of known radius, so its centre is the
point farthest from the cloth), and refines each to the centroid of the mask within one radius,
iterated until it no longer moves (a mean shift with a window whose edge weighs pixels by how
much of them it covers, so that the centroid moves smoothly with the window and the iteration
has one fixed point at the ball, not a pixel's worth of them).
:func:`table_positions` takes the pixels back onto the plane of the balls' centres through the
calibrated lens. ``scripts/detect_balls.py`` runs it on ``~camera/image_raw`` and scores it
against ``~camera/ground_truth``.
"""

from __future__ import annotations

import cv2
import numpy as np

#: How far from the cloth's colour a pixel must be to count as something on it (8-bit levels,
#: Euclidean in BGR): above sensor noise and the cloth's shading, below every ball's contrast.
COLOUR_THRESHOLD = 32.0
#: A peak of the distance transform is a ball's centre if it is at least this share of a radius
#: from the cloth: a smeared ball is still a full radius wide, a cushion's edge or a pocket's
#: sliver is not.
PEAK_SHARE = 0.75
#: The refinement stops when a step moves the centre less than this [px]; near a neighbouring
#: ball each step closes about half the remaining error, so a peak a few pixels off takes 20-40.
REFINE_TOLERANCE = 1e-3
#: and after this many steps at most (a bound on the cost of a crowded image).
MAX_REFINEMENTS = 60


def cloth_colour(image: np.ndarray) -> np.ndarray:
    """The cloth's colour: the median of the image's middle ninth (the cloth, mostly)."""
    h, w = image.shape[:2]
    middle = image[h // 3 : 2 * h // 3, w // 3 : 2 * w // 3].reshape(-1, 3)
    return np.median(middle, axis=0)


def colour_distance(image: np.ndarray, colour: np.ndarray) -> np.ndarray:
    """Each pixel's Euclidean distance from ``colour`` in BGR [8-bit levels]."""
    difference = cv2.absdiff(image, np.array([*np.round(colour), 0], np.float64)).astype(np.float32)
    # The channels' squares summed by OpenCV (a 1 x 3 transform), five times numpy's speed: exact,
    # as the squares of 8-bit levels and their sums are integers a float holds.
    squares = cv2.multiply(difference, difference)
    return cv2.sqrt(cv2.transform(squares, np.ones((1, 3), np.float32))).reshape(image.shape[:2])


def cloth_region(image: np.ndarray, cloth: np.ndarray) -> np.ndarray:
    """The playing area: the convex hull of the largest cloth-coloured region, shrunk by 2 px
    so that the cushions' noses stay out. For a camera that does not move, compute it once."""
    near = (colour_distance(image, cloth) < COLOUR_THRESHOLD).astype(np.uint8)
    count, labels, stats, _ = cv2.connectedComponentsWithStats(near, connectivity=4)
    if count < 2:
        return np.zeros(image.shape[:2], np.uint8)
    largest = 1 + int(np.argmax(stats[1:, cv2.CC_STAT_AREA]))
    points = cv2.findNonZero((labels == largest).astype(np.uint8))
    region = np.zeros(image.shape[:2], np.uint8)
    cv2.fillConvexPoly(region, cv2.convexHull(points), 1)
    return cv2.erode(region, np.ones((5, 5), np.uint8))


def detect_balls(image: np.ndarray, radius: float, region: np.ndarray | None = None) -> np.ndarray:
    """Ball centres [px] in a BGR image of the table, as an (N, 2) array of (u, v).

    ``radius`` is a ball's apparent radius in pixels (focal length x R / distance); ``region``
    the playing area (:func:`cloth_region`), found in this image if not given.
    """
    cloth = cloth_colour(image)
    if region is None:
        region = cloth_region(image, cloth)
    on_cloth = colour_distance(image, cloth) >= COLOUR_THRESHOLD
    mask = (on_cloth & (region > 0)).astype(np.uint8)
    distance = cv2.distanceTransform(mask, cv2.DIST_L2, 5)
    # Local maxima at least PEAK_SHARE x radius deep, one within 1.2 radius.
    window = max(3, int(round(1.2 * radius)) | 1)
    dilated = cv2.dilate(distance, cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (window, window)))
    peaks = np.argwhere((distance >= dilated) & (distance >= PEAK_SHARE * radius))
    # Plateaus give several pixels per ball: keep the deepest, then none within 1.2 radius of it.
    order = np.argsort(-distance[peaks[:, 0], peaks[:, 1]])
    kept: list[np.ndarray] = []
    for row, column in peaks[order]:
        p = np.array([column, row], dtype=float)
        if all(np.hypot(*(p - q)) > 1.2 * radius for q in kept):
            kept.append(p)
    centres = [refine(mask, p, radius) for p in kept]
    inner = cv2.erode(region, np.ones((3, 3), np.uint8))
    for i, centre in enumerate(centres):
        if clipped(region, centre, radius):
            others = [c for j, c in enumerate(centres) if j != i]
            centres[i] = rim_centre(mask, inner, centre, radius, others)
    return np.array(centres).reshape(-1, 2)


def clipped(region: np.ndarray, centre: np.ndarray, radius: float) -> bool:
    """Whether the playing area's edge cuts the disc of `radius` around `centre` (a ball at a
    cushion): its mask is cut there, and its centroid pulled off the centre by millimetres."""
    h, w = region.shape
    x0, x1 = int(max(0, centre[0] - radius - 2)), int(min(w, centre[0] + radius + 3))
    y0, y1 = int(max(0, centre[1] - radius - 2)), int(min(h, centre[1] + radius + 3))
    ys, xs = np.mgrid[y0:y1, x0:x1]
    inside = np.hypot(xs - centre[0], ys - centre[1]) <= radius + 1.5
    return bool(np.any(region[y0:y1, x0:x1][inside] == 0)) or x0 == 0 or y0 == 0 or x1 == w or y1 == h


def rim_centre(mask: np.ndarray, inner: np.ndarray, centre: np.ndarray, radius: float, others) -> np.ndarray:
    """The centre of the circle through the ball's own rim, for a ball whose mask the playing
    area's edge cuts: the rim pixels (the mask's edge where the cloth, not the area's edge, bounds
    it; not where a neighbouring ball does) fitted by least squares to a circle (Kasa's algebraic
    fit: linear in the centre and in r^2 - |c|^2). Every rim pixel lies about half a pixel inside
    the true edge, which shrinks the circle and leaves its centre. Falls back to `centre` if too
    little of the rim is seen (under a quarter of it)."""
    h, w = mask.shape
    x0, x1 = int(max(0, centre[0] - radius - 4)), int(min(w, centre[0] + radius + 5))
    y0, y1 = int(max(0, centre[1] - radius - 4)), int(min(h, centre[1] + radius + 5))
    window = mask[y0:y1, x0:x1]
    edge = window & ~cv2.erode(window, cv2.getStructuringElement(cv2.MORPH_CROSS, (3, 3)), borderValue=1)
    edge &= inner[y0:y1, x0:x1]
    ys, xs = np.nonzero(edge)
    points = np.column_stack([xs + x0, ys + y0]).astype(float)
    near = np.abs(np.hypot(*(points - centre).T) - radius) < 4
    for other in others:
        near &= np.hypot(*(points - other).T) > radius + 2
    points = points[near]
    if len(points) < 0.25 * 2 * np.pi * radius:
        return centre
    design = np.column_stack([2 * points, np.ones(len(points))])
    solution, *_ = np.linalg.lstsq(design, (points ** 2).sum(axis=1), rcond=None)
    fitted = solution[:2]
    return fitted if np.hypot(*(fitted - centre)) < radius / 2 else centre


def refine(mask: np.ndarray, centre: np.ndarray, radius: float) -> np.ndarray:
    """The centroid of the mask's pixels within ``radius`` of ``centre``, iterated to its fixed point.

    A pixel on the window's rim weighs what share of it lies inside (its centre within half a
    pixel of the rim: linearly), so the centroid is continuous in ``centre``. With a plain
    inside-or-out window it is piecewise constant, and the iteration can stop a pixel or more
    from the ball wherever a touching neighbour's pixels balance the ball's (seen: 1.6 px on a
    rack's corner ball whose distance-transform peak started 4 px off).
    """
    h, w = mask.shape
    centre = np.asarray(centre, float)
    for _ in range(MAX_REFINEMENTS):
        x0, x1 = int(max(0, centre[0] - radius - 2)), int(min(w, centre[0] + radius + 3))
        y0, y1 = int(max(0, centre[1] - radius - 2)), int(min(h, centre[1] + radius + 3))
        ys, xs = np.mgrid[y0:y1, x0:x1]
        rim = np.clip(radius + 0.5 - np.hypot(xs - centre[0], ys - centre[1]), 0.0, 1.0)
        weights = rim * (mask[y0:y1, x0:x1] > 0)
        total = weights.sum()
        if total == 0:
            break
        moved = np.array([(xs * weights).sum(), (ys * weights).sum()]) / total
        step = np.hypot(*(moved - centre))
        centre = moved
        if step < REFINE_TOLERANCE:
            break
    return centre


def table_positions(pixels: np.ndarray, camera_matrix: np.ndarray, distortion: np.ndarray,
                    rotation: np.ndarray, translation: np.ndarray, height: float) -> np.ndarray:
    """Points [m] in the table frame where the rays of ``pixels`` (N, 2) meet the plane
    z = ``height`` (a ball's radius: the plane of the centres).

    ``rotation`` (3x3) and ``translation`` (3) are the camera's optical frame in the table frame.
    """
    if len(pixels) == 0:
        return np.zeros((0, 3))
    normalised = cv2.undistortPoints(np.asarray(pixels, np.float64).reshape(-1, 1, 2), camera_matrix, distortion)
    rays = np.hstack([normalised.reshape(-1, 2), np.ones((len(pixels), 1))]) @ rotation.T
    t = (height - translation[2]) / rays[:, 2]
    return translation + rays * t[:, None]


def match(detected: np.ndarray, truth: np.ndarray, gate: float) -> tuple[np.ndarray, np.ndarray]:
    """Pairs each true position (M, k) with its nearest detection (N, k) within ``gate``, greedily
    by distance. Returns the distances of the matched pairs and a bool array of the true
    positions found."""
    pairs = sorted((float(np.linalg.norm(d - t)), i, j) for i, t in enumerate(truth) for j, d in enumerate(detected))
    found = np.zeros(len(truth), bool)
    used = np.zeros(len(detected), bool)
    errors = []
    for distance, i, j in pairs:
        if distance > gate or found[i] or used[j]:
            continue
        found[i] = used[j] = True
        errors.append(distance)
    return np.array(errors), found
