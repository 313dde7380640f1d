"""The capacity map: du against the direction of the support movement (`directions`: the grid and
tables), as a campaign with the rigid limits beside it (`campaign`), what explains its differences
(`explained`) and the paper's arch's map (`paper`)."""
