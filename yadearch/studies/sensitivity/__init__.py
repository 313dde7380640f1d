"""What du is sensitive to: the factors, Saltelli sample and Sobol indices (`indices`), the study as
campaigns with its tables, figures and report (`study`), and its runs checked by the other engine
(`checks`)."""
