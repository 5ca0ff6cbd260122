package org.libmoa;

/** One entry of libmoa's parameter table. */
public final class ParameterInfo {
  private final String name;
  private final String description;
  private final double defaultValue;
  private final double minValue;
  private final double maxValue;
  private final boolean integral;

  ParameterInfo(NativeParam p) {
    name = p.getName();
    description = p.getDescription();
    defaultValue = p.getDefault_value();
    minValue = p.getMin_value();
    maxValue = p.getMax_value();
    integral = p.getIntegral();
  }

  public String name() {
    return name;
  }

  public String description() {
    return description;
  }

  public double defaultValue() {
    return defaultValue;
  }

  public double minValue() {
    return minValue;
  }

  public double maxValue() {
    return maxValue;
  }

  /** Only whole numbers are accepted. */
  public boolean isIntegral() {
    return integral;
  }
}
