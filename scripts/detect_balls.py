#!/usr/bin/python3
"""An example ball detector on the simulated camera (ROS node).

Subscribes to the table node's ~camera/image_raw and ~camera/ground_truth, finds the balls
(cue_sim.detection: the cloth's colour learnt from the image, a distance transform, centroids),
takes them onto the table through the calibration and the camera's pose in tf, publishes them
as a geometry_msgs/PoseArray on ~detections in the table frame, and logs its error in
millimetres against the ground truth every `~report_every` frames. With ~save it writes the
first image with its detections drawn (README's figure). ~queue_size (1) images, and as many
detections, wait their turn: 1 drops what it has no time for (live), more finds the balls in
every image, late, and publishes every image's detections (a recording).

  rosrun cue_sim detect_balls.py _save:=/tmp/detections.png
"""
import numpy as np
import rospy
import tf2_ros
from cv_bridge import CvBridge
from geometry_msgs.msg import Pose, PoseArray
from sensor_msgs.msg import CameraInfo, Image

from cue_sim import detection
from cue_sim.msg import CameraGroundTruth


def quaternion_matrix(q):
    x, y, z, w = q.x, q.y, q.z, q.w
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


class Detector:
    """Detections per image, scored against the ground truth with the same stamp."""

    def __init__(self, camera_ns, table_frame, ball_radius, queue_size=1):
        self.table_frame = table_frame
        self.ball_radius = ball_radius
        self.bridge = CvBridge()
        self.tf = tf2_ros.Buffer()
        self.listener = tf2_ros.TransformListener(self.tf)
        self.info = None
        self.truths = {}
        self.results = []  # (found, visible, errors [mm]) per scored image
        rospy.Subscriber(camera_ns + "/camera_info", CameraInfo, self.on_info, queue_size=1)
        rospy.Subscriber(camera_ns + "/ground_truth", CameraGroundTruth, self.on_truth, queue_size=10)
        rospy.Subscriber(camera_ns + "/image_raw", Image, self.on_image, queue_size=queue_size, buff_size=2 ** 24)
        # The detections wait as the images do: a detector behind its images publishes back to
        # back, faster than a queue of 1 reaches a recorder on a busy machine.
        self.publisher = rospy.Publisher("~detections", PoseArray, queue_size=queue_size)
        self.last_image = None
        self.region = None

    def on_info(self, info):
        self.info = info

    def on_truth(self, truth):
        self.truths[truth.header.stamp] = truth
        while len(self.truths) > 30:
            self.truths.pop(min(self.truths))

    def camera_pose(self, frame, stamp):
        t = self.tf.lookup_transform(self.table_frame, frame, rospy.Time(0), rospy.Duration(1.0))
        r = quaternion_matrix(t.transform.rotation)
        p = t.transform.translation
        return r, np.array([p.x, p.y, p.z])

    def on_image(self, msg):
        if self.info is None:
            return
        image = self.bridge.imgmsg_to_cv2(msg, "bgr8")
        k = np.array(self.info.K).reshape(3, 3)
        d = np.array(self.info.D)
        rotation, translation = self.camera_pose(msg.header.frame_id, msg.header.stamp)
        radius = k[0, 0] * self.ball_radius / (translation[2] - self.ball_radius)
        if self.region is None or self.region.shape != image.shape[:2]:
            self.region = detection.cloth_region(image, detection.cloth_colour(image))  # the camera does not move
        pixels = detection.detect_balls(image, radius, self.region)
        positions = detection.table_positions(pixels, k, d, rotation, translation, self.ball_radius)
        detections = PoseArray()
        detections.header.stamp = msg.header.stamp
        detections.header.frame_id = self.table_frame
        for x, y, z in positions:
            pose = Pose()
            pose.position.x, pose.position.y, pose.position.z = x, y, z
            pose.orientation.w = 1.0
            detections.poses.append(pose)
        self.publisher.publish(detections)
        self.last_image = (image, pixels, radius)
        truth = self.truths.get(msg.header.stamp)
        if truth is None:
            return
        visible = [b for b in truth.balls if b.visible]
        true_xy = np.array([[b.position.x, b.position.y] for b in visible]).reshape(-1, 2)
        errors, found = detection.match(positions[:, :2], true_xy, gate=2 * self.ball_radius)
        self.results.append((int(found.sum()), len(visible), len(positions), 1000 * errors))


def draw(image, pixels, radius, path):
    import cv2

    out = image.copy()
    for u, v in pixels:
        cv2.circle(out, (int(round(u)), int(round(v))), int(round(radius + 2)), (255, 255, 0), 2, cv2.LINE_AA)
        cv2.drawMarker(out, (int(round(u)), int(round(v))), (0, 0, 255), cv2.MARKER_CROSS, 8, 1)
    cv2.imwrite(path, out)


#: glibc's mallopt parameters and the values the detector sets (mallopt(3)): an image's
#: intermediates (up to 28 MB, a 1920x1200 float colour image) come from the heap and are reused.
M_TRIM_THRESHOLD, M_MMAP_THRESHOLD = -1, -3
MMAP_THRESHOLD = 32 << 20  # glibc's largest allowed on 64-bit
TRIM_THRESHOLD = 128 << 20


def reuse_image_buffers():
    """Keeps an image's large intermediates (numpy's and OpenCV's, 1.7 to 28 MB) in the heap
    between images. glibc maps each buffer over 128 kB afresh and unmaps it when freed, and every
    fresh page then costs a page fault: on a VM where those are dear that made the detection of a
    960x600 image take 51 ms, against 8.5 ms with the buffers reused (2026-11-29), too slow for a
    30 Hz camera. False if this libc has no mallopt."""
    import ctypes

    try:
        libc = ctypes.CDLL("libc.so.6")
    except OSError:
        return False
    return bool(libc.mallopt(M_MMAP_THRESHOLD, MMAP_THRESHOLD)) and bool(libc.mallopt(M_TRIM_THRESHOLD, TRIM_THRESHOLD))


def main():
    rospy.init_node("detect_balls")
    if not reuse_image_buffers():
        rospy.logwarn("detect_balls: mallopt refused; each image's buffers are mapped afresh (slower)")
    camera_ns = rospy.get_param("~camera", "/table/camera")
    # ~queue_size: 1 (live) keeps only the newest image, dropping those it has no time for; a
    # recording (calibration_record.launch) keeps more, and finds the balls in every image, late.
    detector = Detector(camera_ns, rospy.get_param("~table_frame", "table"),
                        rospy.get_param("~ball_radius", rospy.get_param("/table/ball_radius", 0.028575)),
                        int(rospy.get_param("~queue_size", 1)))
    report_every = rospy.get_param("~report_every", 30)
    save = rospy.get_param("~save", "")
    reported = 0
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        rate.sleep()
        if save and detector.last_image is not None:
            draw(*detector.last_image, save)
            rospy.loginfo("detect_balls: wrote %s", save)
            save = ""
        if len(detector.results) - reported >= report_every:
            recent = detector.results[reported:]
            reported = len(detector.results)
            errors = np.concatenate([r[3] for r in recent]) if recent else np.zeros(0)
            rospy.loginfo("detect_balls: %d of %d visible balls found in %d images (%d detections), error mean %.2f mm, "
                          "max %.2f mm", sum(r[0] for r in recent), sum(r[1] for r in recent), len(recent),
                          sum(r[2] for r in recent), errors.mean() if errors.size else float("nan"),
                          errors.max() if errors.size else float("nan"))


if __name__ == "__main__":
    main()
