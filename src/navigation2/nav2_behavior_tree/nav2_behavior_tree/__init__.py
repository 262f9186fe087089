"""Nav2's behavior trees in Python: a BehaviorTree.CPP v4 XML reader and tick engine with
Nav2's node set (upstream's nav2_behavior_tree)."""
