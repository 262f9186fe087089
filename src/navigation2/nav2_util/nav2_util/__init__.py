"""What Nav2's Python servers share (upstream's nav2_util, the parts they use)."""
