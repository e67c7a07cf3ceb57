"""Rotations and angle units as MuJoCo computes them: Euler sequences, degrees and radians.

>>> import math
>>> [round(c, 12) + 0 for c in euler_quat([math.pi / 2, 0, 0], "xyz")]
[0.707106781187, 0.707106781187, 0.0, 0.0]
>>> [round(a, 12) + 0 for a in euler_angles(euler_quat([0.1, 0.2, 0.3], "xyz"), "xyz")]
[0.1, 0.2, 0.3]
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

__all__ = [
    "ORIENTATIONS",
    "euler_angles",
    "euler_product",
    "euler_quat",
    "in_unit",
    "joint_radians",
    "orientation_radians",
    "quat_distance",
    "quat_product",
]

#: The attributes that orient a body, frame, geom, site, camera or inertial.
ORIENTATIONS = ("quat", "axisangle", "xyaxes", "zaxis", "euler")


def quat_product(a: Sequence[float], b: Sequence[float]) -> tuple[float, float, float, float]:
    """The quaternion product ``a * b`` (``w, x, y, z``): turn by ``b``, then by ``a``.

    Examples:
        >>> quat_product((0, 1, 0, 0), (0, 1, 0, 0))
        (-1, 0, 0, 0)

    """
    return (
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    )


def euler_product(angles: Sequence[float], sequence: str) -> tuple[float, ...]:
    """The product of the turns of Euler angles in radians, before MuJoCo normalizes it.

    MuJoCo multiplies this product out of ``euler`` and normalizes it once; it
    normalizes a written ``quat`` once too, so this product written as ``quat``
    compiles to exactly the quaternion the Euler angles compile to (normalizing
    it here would round it a second time).

    Examples:
        >>> import math
        >>> [round(c, 6) + 0 for c in euler_product([0, 0, math.pi], "xyz")]
        [0.0, 0.0, 0.0, 1.0]

    """
    quat: tuple[float, ...] = (1.0, 0.0, 0.0, 0.0)
    for angle, axis in zip(angles, sequence, strict=True):
        turn = [math.cos(angle / 2), 0.0, 0.0, 0.0]
        turn[1 + "xyz".index(axis.lower())] = math.sin(angle / 2)
        quat = quat_product(quat, turn) if axis.islower() else quat_product(turn, quat)
    return quat


def euler_quat(angles: Sequence[float], sequence: str) -> tuple[float, ...]:
    """MuJoCo's quaternion for Euler angles in radians: lower case axes turn with the frame.

    Examples:
        >>> import math
        >>> [round(c, 6) + 0 for c in euler_quat([0, 0, math.pi], "xyz")]
        [0.0, 0.0, 0.0, 1.0]

    """
    quat = euler_product(angles, sequence)
    norm = math.sqrt(sum(c * c for c in quat))
    return tuple(c / norm for c in quat)


def quat_distance(a: Sequence[float], b: Sequence[float]) -> float:
    """The largest difference between two quaternions' components (signs matter).

    Examples:
        >>> quat_distance((1, 0, 0, 0), (0.5, 0, 0, 0))
        0.5

    """
    return max(abs(x - y) for x, y in zip(a, b, strict=True))


def euler_angles(quat: Sequence[float], sequence: str) -> tuple[float, ...] | None:
    """Euler angles (radians) in ``sequence`` giving ``quat`` itself (not ``-quat``).

    ``None`` when two rotations that follow each other turn about one axis.

    Examples:
        >>> import math
        >>> [round(a, 9) + 0 for a in euler_angles(euler_quat([0.3, 0, 0], "xyz"), "zyx")]
        [0.0, 0.0, 0.3]
        >>> euler_angles((1, 0, 0, 0), "xxz") is None
        True

    """
    order: list[tuple[int, int]] = []  # (axis, angle index) in the order the rotations multiply
    for index, axis in enumerate(sequence):
        item = ("xyz".index(axis.lower()), index)
        order.append(item) if axis.islower() else order.insert(0, item)
    (i, first), (j, second), (k, third) = order
    if i == j or j == k:
        return None
    w, x, y, z = quat
    m = (
        (1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)),
        (2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)),
        (2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)),
    )
    sign = 1.0 if (j - i) % 3 == 1 else -1.0
    if i != k:  # Tait-Bryan: i, j, k all differ
        middle = math.atan2(sign * m[i][k], math.hypot(m[i][i], m[i][j]))
        general = (math.atan2(-sign * m[j][k], m[k][k]), math.atan2(-sign * m[i][j], m[i][i]))
        locked = (math.atan2(sign * m[k][j], m[j][j]), 0.0)
    else:  # proper Euler: i, j, i
        k = 3 - i - j
        middle = math.atan2(math.hypot(m[i][j], m[i][k]), m[i][i])
        general = (math.atan2(m[j][i], -sign * m[k][i]), math.atan2(m[i][j], sign * m[i][k]))
        locked = (math.atan2(-sign * m[j][k], m[j][j]), 0.0)
    candidates = []
    for outer, inner in (general, locked):  # near gimbal lock the second is the accurate one
        angles = [0.0, 0.0, 0.0]
        angles[first], angles[second], angles[third] = outer, middle, inner
        made = euler_quat(angles, sequence)
        negated = quat_distance(made, quat) > quat_distance([-c for c in made], quat)
        if negated:  # one more turn about the first axis gives the same rotation, negated
            angles[first] += -2 * math.pi if angles[first] > 0 else 2 * math.pi
        candidates.append((quat_distance(euler_quat(angles, sequence), quat), tuple(angles)))
    return min(candidates)[1]


def orientation_radians(degrees: float) -> float:
    """Degrees in radians, computed as MuJoCo converts ``euler`` and ``axisangle``.

    Examples:
        >>> orientation_radians(180.0)
        3.141592653589793

    """
    return degrees / 180 * math.pi


def joint_radians(degrees: float) -> float:
    """Degrees in radians, computed as MuJoCo converts joint ranges and references.

    Examples:
        >>> joint_radians(90.0)
        1.5707963267948966

    """
    return degrees * (math.pi / 180)


def in_unit(radians: float, degree: bool, reading: Callable[[float], float]) -> float:
    """The number MuJoCo reads as ``radians`` in the unit (exactly, where a double does it).

    Examples:
        >>> in_unit(1.5707963267948966, True, joint_radians), in_unit(0.5, False, joint_radians)
        (90.0, 0.5)

    """
    if not degree:
        return radians
    guess = radians * 180 / math.pi
    for candidate in (guess, math.nextafter(guess, math.inf), math.nextafter(guess, -math.inf)):
        if reading(candidate) == radians:
            return candidate
    return guess
