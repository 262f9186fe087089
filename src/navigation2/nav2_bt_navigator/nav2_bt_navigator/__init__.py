"""Nav2 BT navigator in Python: bt_navigator and its two navigators."""
