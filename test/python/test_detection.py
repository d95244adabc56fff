"""The example detector's refinement (cue_sim.detection), on synthetic images with known centres.

Two balls touch on the cloth, as in a rack; one has a pixel the colour of the cloth inside it
(the anti-aliased rim of its number's disc does this in the camera's images), so its
distance-transform peak starts pixels away from its centre. The refinement must still end at
the centre, from any start within half a radius.
"""
import cv2
import numpy as np
import pytest

from cue_sim import detection

CLOTH = (56, 128, 13)
RADIUS = 16.45  # [px] a ball's image from 2.4 m with the bundled calibration


def disc(image, centre, radius, colour, samples=8):
    """Paints a disc into `image` with each pixel blended by the share of it the disc covers
    (`samples` x `samples` points a pixel; pixel centres at integer coordinates, as in ROS'
    camera model)."""
    offsets = (np.arange(samples) + 0.5) / samples - 0.5
    ys, xs = np.mgrid[0 : image.shape[0], 0 : image.shape[1]]
    coverage = np.zeros(image.shape[:2])
    for dy in offsets:
        for dx in offsets:
            coverage += np.hypot(xs + dx - centre[0], ys + dy - centre[1]) <= radius
    coverage /= samples * samples
    blended = image * (1 - coverage[..., None]) + np.array(colour, float) * coverage[..., None]
    image[:] = np.round(blended).astype(np.uint8)


def touching_pair(centre, towards):
    """An image with a dark green ball at `centre` touching a white one in direction `towards`."""
    image = np.zeros((120, 160, 3), np.uint8)
    image[:] = CLOTH
    direction = np.asarray(towards, float) / np.linalg.norm(towards)
    disc(image, centre + 2 * RADIUS * direction, RADIUS, (230, 230, 230))
    disc(image, centre, RADIUS, (21, 53, 0))
    hole = np.round(centre + [8.0, -4.0]).astype(int)
    image[hole[1], hole[0]] = CLOTH
    return image


@pytest.mark.parametrize("towards", [(0, -1), (-1, 0), (-1, -1), (1, -2)])
@pytest.mark.parametrize("start", [(-4.0, 0.0), (0.0, 5.0), (3.0, -3.0), (6.0, 4.0)])
def test_a_ball_touching_another_is_refined_to_its_centre(towards, start):
    centre = np.array([80.3, 70.6])
    image = touching_pair(centre, towards)
    mask = (detection.colour_distance(image, np.array(CLOTH, float)) >= detection.COLOUR_THRESHOLD).astype(np.uint8)
    refined = detection.refine(mask, centre + start, RADIUS)
    assert np.hypot(*(refined - centre)) < 0.15, f"refined to {refined}, the ball is at {centre}"


def test_the_detector_finds_both_balls_to_a_tenth_of_a_pixel():
    centre = np.array([80.3, 70.6])
    image = touching_pair(centre, (-1, -1))
    found = detection.detect_balls(image, RADIUS, np.ones(image.shape[:2], np.uint8))
    truth = np.array([centre, centre + 2 * RADIUS * np.array([-1.0, -1.0]) / np.sqrt(2)])
    errors, matched = detection.match(found, truth, RADIUS)
    assert matched.all() and len(found) == 2
    assert errors.max() < 0.15


@pytest.mark.parametrize("inside", [0.6, 0.85, 1.0])
def test_a_ball_at_the_cushion_is_found_at_its_centre_not_its_visible_part(inside):
    """A ball whose disc the playing area's edge cuts (a ball at a cushion: the area ends a little
    inside the nose) is found from its own rim: the centroid of what is left of it is pixels off."""
    image = np.zeros((120, 160, 3), np.uint8)
    image[:] = CLOTH
    edge = 100  # the playing area ends at this column
    centre = np.array([edge - inside * RADIUS, 60.4])
    disc(image, centre, RADIUS, (40, 40, 200))
    region = np.ones(image.shape[:2], np.uint8)
    region[:, edge:] = 0
    found = detection.detect_balls(image, RADIUS, region)
    assert len(found) == 1
    assert np.hypot(*(found[0] - centre)) < 0.25, (found[0], centre)
    if inside < 0.9:  # what the centroid alone gives when a tenth of the disc or more is cut: a pixel off
        mask = (detection.colour_distance(image, np.array(CLOTH, float)) >= detection.COLOUR_THRESHOLD) & (region > 0)
        assert np.hypot(*(detection.refine(mask.astype(np.uint8), centre, RADIUS) - centre)) > 1.0
