"""Range facts for ROS int64 fields, shared by the AddTwoInts server and client."""

INT64_MIN = -(2**63)
INT64_MAX = 2**63 - 1
INT64_RANGE = f'[{INT64_MIN}, {INT64_MAX}]'


def fits_int64(value: int) -> bool:
    return INT64_MIN <= value <= INT64_MAX
