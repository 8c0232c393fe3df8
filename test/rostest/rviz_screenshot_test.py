#!/usr/bin/env python3
"""rostest: rviz/segmentation.rviz loads under Xvfb and its screenshot shows segmented objects.

The bundled bag is replayed and segmented (bag of demo.launch, without its rviz); once objects
are published, scripts/rviz_screenshot renders the configuration. Segmented points, plane
patches and arrows are drawn in saturated object colours, while the input cloud is grey and
the background dark: a screenshot without segments has next to no saturated pixels.
"""
import os
import subprocess
import sys
import tempfile
import unittest

import rospy
import rostest
from PIL import Image

from symmetry_segmentation.msg import SegmentedObjectArray


def saturated_pixels(path, left):
    image = Image.open(path).convert("RGB")
    width, height = image.size
    count = 0
    for y in range(0, height, 2):
        for x in range(left, width, 2):
            r, g, b = image.getpixel((x, y))
            if max(r, g, b) - min(r, g, b) > 90 and max(r, g, b) > 120:
                count += 1
    return count, image.size


def rviz_log_tail(screenshot):
    try:
        with open(screenshot[:-len(".png")] + ".rviz.log") as log:
            return "".join(log.readlines()[-20:])
    except OSError as error:
        return str(error)


class RvizScreenshot(unittest.TestCase):
    def test_screenshot_shows_segmented_objects(self):
        objects = rospy.wait_for_message("/segmentation/objects", SegmentedObjectArray, timeout=120)
        self.assertGreaterEqual(len(objects.objects), 3)
        script = rospy.get_param("~script")
        directory = tempfile.mkdtemp(prefix="rviz_screenshot_")
        # rviz starts slowly under software rendering while the node segments on both cores, and
        # each restart of the looping bag clears rviz's displays until the next segmentation
        # arrives: the script keeps the best of several shots, and a further run is allowed.
        counts = []
        for attempt in range(3):
            output = os.path.join(directory, "segmentation_%d.png" % attempt)
            result = subprocess.run([script, output, "--wait", "15", "--best-of", "8"], capture_output=True, text=True, timeout=120)
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
            # The 3D view is right of the Displays panel (about 360 px wide).
            count, size = saturated_pixels(output, 360)
            self.assertEqual(size, (1100, 720))
            counts.append(count)
            sys.stderr.write("rviz screenshot %s: %d object-coloured pixels\n" % (output, count))
            if count > 1500:
                break
        # Under the sanitizers (scripts/test --sanitize) the node takes several seconds per cloud,
        # longer than a loop of the 2 s bag, whose restart clears rviz's tf buffer: the markers'
        # stamps are gone by the time they arrive and nothing is drawn. There the test checks the
        # objects and that rviz renders the configuration, not what it draws.
        if os.environ.get("SYMSEG_SANITIZE"):
            return
        # Measured: about 6700 sampled pixels (every 4th) with the bundled scene; a handful
        # (icons) without segmented objects.
        self.assertGreater(count, 1500, "too few object-coloured pixels in %s (each try: %s); rviz log:\n%s"
                           % (output, counts, rviz_log_tail(output)))


if __name__ == "__main__":
    rospy.init_node("rviz_screenshot_test")
    rostest.rosrun("symmetry_segmentation", "rviz_screenshot", RvizScreenshot, sys.argv)
