#!/usr/bin/env python3
"""Peer pipeline for the benchmarks: normals from a height map with OpenCV, the way a
pipeline engineer would write it (cv2.Sobel on both axes, then normalise the vector).

  opencv_normals.py WIDTH HEIGHT RAW RUNS   (bench-generate) reads raw float32 heights and
      prints the median milliseconds of the compute alone (no file I/O) over RUNS runs;
  opencv_normals.py --files IN.png OUT.png  (tools/bench-cli) the whole job as a script does
      it: read a 16-bit height PNG, compute, write a 16-bit normal PNG (cv2.imwrite defaults)."""
import sys
import time

import cv2
import numpy as np


def normals(height, strength):
    gx = cv2.Sobel(height, cv2.CV_32F, 1, 0, ksize=3, scale=1.0 / 8.0,
                   borderType=cv2.BORDER_REFLECT_101)
    gy = cv2.Sobel(height, cv2.CV_32F, 0, 1, ksize=3, scale=1.0 / 8.0,
                   borderType=cv2.BORDER_REFLECT_101)
    nx = -strength * gx
    ny = strength * gy  # rows grow downward; +Y up the image
    inverse = 1.0 / np.sqrt(nx * nx + ny * ny + 1.0)
    return cv2.merge([nx * inverse * 0.5 + 0.5, ny * inverse * 0.5 + 0.5, inverse * 0.5 + 0.5])


def whole_job(source, target):
    field = cv2.imread(source, cv2.IMREAD_UNCHANGED).astype(np.float32) / 65535.0
    rgb = normals(field, 4.0)
    bgr = rgb[:, :, ::-1]
    cv2.imwrite(target, np.clip(bgr * 65535.0 + 0.5, 0, 65535).astype(np.uint16))


def main():
    if sys.argv[1] == "--files":
        whole_job(sys.argv[2], sys.argv[3])
        return
    width, height, path, runs = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3], int(sys.argv[4])
    field = np.fromfile(path, dtype=np.float32).reshape(height, width)
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        result = normals(field, 4.0)
        times.append((time.perf_counter() - start) * 1000.0)
    assert result.shape == (height, width, 3)
    print("%.1f" % sorted(times)[len(times) // 2])


if __name__ == "__main__":
    main()
