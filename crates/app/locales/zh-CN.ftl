### quarter-car

quarter-car-legend-comfort = 舒适 { $low }、{ $high }
quarter-car-legend-performance = 运动 { $low }、{ $high }
quarter-car-legend-critical = 临界 { $zeta }（×）
quarter-car-legend-overdamped = 过阻尼 { $zeta }（●）
quarter-car-group = { $group ->
        [comfort] 舒适
        [performance] 运动
        [critical] 临界
       *[overdamped] 过阻尼
    }
quarter-car-crossings = { $count ->
        [0] 不穿越平衡位置
        [1] 稳定前穿越平衡位置一次
       *[other] 稳定前穿越平衡位置 { $count } 次
    }
quarter-car-crossings-inside-band = 未穿越平衡位置即已稳定（其回弹留在误差带内）
quarter-car-settles-after = { $time } 后保持在静止位置附近 x₀ 的 ±{ $band } 以内
quarter-car-does-not-settle = 不能稳定
quarter-car-rebound = 最大回弹 { $rebound }（t = { $time }）
quarter-car-no-rebound = 无回弹
quarter-car-describe-design = 当前设计（ζ = { $zeta }，{ $regime }）：{ $crossings }，{ $settling }，{ $rebound }。
quarter-car-describe-undamped = 当前设计（ζ = 0，无阻尼）：以 { $frequency } 在 ±{ $amplitude } 之间永远振荡。
quarter-car-describe-unsettled = 当前设计（{ $regime }）：不能稳定。
quarter-car-list-separator = {"；"}
quarter-car-describe-response = { $design }本车上的各预设设定进入 x₀ 的 ±{ $band } 误差带：{ $family }。
quarter-car-member-settles = { $group } ζ = { $zeta } 用时 { $time }
quarter-car-member-unsettled = { $group } ζ = { $zeta } 不能稳定
quarter-car-two-sentences = { $first }{ $second }
quarter-car-settling-fastest = 本车自由响应进入 x₀ 的 ±{ $band } 误差带的调节时间随 ζ 的变化：ζ = { $zeta } 时最快（{ $time }），恰在一次跳变之后；每当一次回弹落入误差带内，调节时间就向下跳变。
quarter-car-settling-curve = 自由响应进入 x₀ 的 ±{ $band } 误差带的调节时间随 ζ 的变化。
quarter-car-settling-design = 当前设计 ζ = { $zeta }，调节时间为 { $time }。
quarter-car-settling-design-never = 当前设计 ζ = { $zeta }，永远不能稳定。
quarter-car-sensitivity-range = 簧上质量在 { $low } 到 { $high } 之间（±{ $variation }）且阻尼器和弹簧不变时，ζ 从 { $min } 变化到 { $max }（标称值 { $nominal }）；线性估计为 { $linear_min } 到 { $linear_max }。
quarter-car-sensitivity-undefined = 此设计的阻尼比范围无定义。
quarter-car-sensitivity-inside = 调节最快的 ζ = { $zeta } 位于此范围内：使 ζ 低于该值的载荷会使调节明显变慢。
quarter-car-sensitivity-outside = 调节最快的 ζ = { $zeta } 位于此范围之外。
quarter-car-schematic = 四分之一车辆，t = { $time }：车身{ $side ->
        [above] 高于
       *[below] 低于
    }静止位置 { $displacement }，路面固定。
quarter-car-settling-title = 进入 x₀ 的 ±{ $band } 误差带的调节时间随 ζ 的变化
quarter-car-axis-zeta = 阻尼比 ζ
quarter-car-axis-zeta-fastest = 阻尼比 ζ（虚线：最快 ζ = { $zeta }）
quarter-car-axis-settling-time = 调节时间 t_s
quarter-car-axis-sprung-mass = 簧上质量 m
quarter-car-fastest = 最快 ζ = { $zeta }
quarter-car-this-design = 当前设计
quarter-car-nominal = 标称值
quarter-car-road = 路面
quarter-car-band-label = x₀ 的 ±{ $band }
quarter-car-series-design = 当前设计，ζ { $zeta }
quarter-car-title = 四分之一车辆悬架
quarter-car-summary = 汽车的一个角：车身（簧上质量 m）支承在弹簧 k 和阻尼器 c 上，下方路面固定；车身被推离 x₀ 后从静止释放（x′(0) = 0）。c 和 ζ 是同一个阻尼器的两种表示，c = 2ζ√(km)：移动其中一个，另一个随之改变；改变 m 或 k 时阻尼器不变，因此 ζ 随之改变。细曲线是本车上的教科书式设定：舒适型（ζ ≈ 0.3–0.4）有回弹，运动型（ζ ≈ 0.65–0.7）稳定最快，临界（ζ = 1）和过阻尼设定无回弹地返回，但更慢。当 ζ 经过使某次回弹落入误差带内的数值时，调节时间发生跳变：最快的 ζ 恰好位于这样一次跳变之后，因此更重的载荷可能使调校良好的车越过这一边缘（见质量条带图）。调节以这一自由响应衡量：调节时间是 |x| 最后一次等于 误差带·|x₀| 的时刻，此后车身保持在静止位置的 ±误差带·|x₀| 以内（而不是阶跃响应终值附近的误差带）。
quarter-car-param-m = 簧上质量
quarter-car-param-k = 弹簧刚度
quarter-car-param-c = 阻尼器阻尼系数
quarter-car-param-zeta = 阻尼比
quarter-car-param-x0 = 初始位移
quarter-car-param-band = 静止位置附近的调节误差带（相对于 x₀）
quarter-car-param-dm = 簧上质量变化
quarter-car-readout-regime = 阻尼状态
quarter-car-readout-wn = 固有频率 ωₙ
quarter-car-readout-fn = 固有频率 fₙ
quarter-car-readout-zeta = 阻尼比 ζ
quarter-car-readout-c = 当前阻尼系数 c
quarter-car-readout-c-crit = 临界阻尼 2√(km)
quarter-car-readout-wd = 阻尼频率 ω_d
quarter-car-readout-settling-time = 进入 ±误差带·|x₀| 的调节时间 t_s（自由响应）
quarter-car-readout-overshoot = 最大回弹（相对于 x₀）
quarter-car-readout-peak-time = 最大回弹时刻
quarter-car-readout-zeta-argmin = 调节最快的 ζ（自由响应，相同误差带）
quarter-car-readout-settling-min = 其调节时间
quarter-car-readout-zeta-lo = 质量 +dm % 时的 ζ
quarter-car-readout-zeta-hi = 质量 −dm % 时的 ζ
quarter-car-plot-response = 车身位移 x(t)
quarter-car-plot-settling = 自由响应调节时间随 ζ 的变化
quarter-car-plot-sensitivity = 簧上质量变化时的 ζ
quarter-car-preset-1 = 舒适 ζ = 0.3
quarter-car-preset-2 = 舒适 ζ = 0.4
quarter-car-preset-3 = 运动 ζ = 0.65
quarter-car-preset-4 = 运动 ζ = 0.7
quarter-car-preset-5 = 临界 ζ = 1
quarter-car-preset-6 = 过阻尼 ζ = 2

