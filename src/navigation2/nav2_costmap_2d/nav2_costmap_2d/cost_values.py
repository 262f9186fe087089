"""Nav2's cost values (nav2_costmap_2d/cost_values.hpp): what a master costmap cell holds."""

NO_INFORMATION = 255
LETHAL_OBSTACLE = 254
INSCRIBED_INFLATED_OBSTACLE = 253
MAX_NON_OBSTACLE = 252
FREE_SPACE = 0
