### quarter-car

quarter-car-legend-comfort = conforto { $low } e { $high }
quarter-car-legend-performance = esportivo { $low } e { $high }
quarter-car-legend-critical = crítico { $zeta } (×)
quarter-car-legend-overdamped = superamortecido { $zeta } (●)
quarter-car-group = { $group ->
        [comfort] conforto
        [performance] esportivo
        [critical] crítico
       *[overdamped] superamortecido
    }
quarter-car-crossings = { $count ->
        [0] não cruza o equilíbrio
        [one] cruza o equilíbrio uma vez antes de se acomodar
       *[other] cruza o equilíbrio { $count } vezes antes de se acomodar
    }
quarter-car-crossings-inside-band = acomoda-se antes de cruzar o equilíbrio (seu ressalto fica dentro da faixa)
quarter-car-settles-after = fica dentro de ±{ $band } de x₀ em torno do repouso após { $time }
quarter-car-does-not-settle = não se acomoda
quarter-car-rebound = ressalto máximo de { $rebound } em { $time }
quarter-car-no-rebound = sem ressalto
quarter-car-describe-design = Este ajuste (ζ = { $zeta }, { $regime }): { $crossings }, { $settling }, { $rebound }.
quarter-car-describe-undamped = Este ajuste (ζ = 0, não amortecido): oscila indefinidamente entre ±{ $amplitude } a { $frequency }.
quarter-car-describe-unsettled = Este ajuste ({ $regime }): não se acomoda.
quarter-car-list-separator = {"; "}
quarter-car-describe-response = { $design } Ajustes de referência neste carro, com acomodação em ±{ $band } de x₀: { $family }.
quarter-car-member-settles = { $group } ζ = { $zeta } em { $time }
quarter-car-member-unsettled = { $group } ζ = { $zeta } não se acomoda
quarter-car-two-sentences = { $first } { $second }
quarter-car-settling-fastest = Tempo de acomodação da resposta livre em ±{ $band } de x₀ em função de ζ para este carro: o mais rápido é ζ = { $zeta } ({ $time }), logo após um salto; ele cai bruscamente cada vez que um ressalto passa para dentro da faixa.
quarter-car-settling-curve = Tempo de acomodação da resposta livre em ±{ $band } de x₀ em função de ζ.
quarter-car-settling-design = Este ajuste, ζ = { $zeta }, acomoda-se em { $time }.
quarter-car-settling-design-never = Este ajuste, ζ = { $zeta }, nunca se acomoda.
quarter-car-sensitivity-range = Com a massa suspensa entre { $low } e { $high } (±{ $variation }) e o mesmo amortecedor e a mesma mola, ζ vai de { $min } a { $max } (nominal { $nominal }); a estimativa linear é de { $linear_min } a { $linear_max }.
quarter-car-sensitivity-undefined = A faixa da razão de amortecimento não está definida para este ajuste.
quarter-car-sensitivity-inside = O ζ de acomodação mais rápida, { $zeta }, está dentro desta faixa: cargas que levam ζ abaixo dele se acomodam bem mais tarde.
quarter-car-sensitivity-outside = O ζ de acomodação mais rápida, { $zeta }, está fora desta faixa.
quarter-car-schematic = Quarto de veículo em t = { $time }: a carroceria está { $displacement } { $side ->
        [above] acima
       *[below] abaixo
    } do repouso, pista fixa.
quarter-car-settling-title = Tempo de acomodação em ±{ $band } de x₀ em função de ζ
quarter-car-axis-zeta = razão de amortecimento ζ
quarter-car-axis-zeta-fastest = razão de amortecimento ζ (tracejado: ζ mais rápido = { $zeta })
quarter-car-axis-settling-time = tempo de acomodação t_s
quarter-car-axis-sprung-mass = massa suspensa m
quarter-car-fastest = ζ mais rápido = { $zeta }
quarter-car-this-design = este ajuste
quarter-car-nominal = nominal
quarter-car-road = pista
quarter-car-band-label = ±{ $band } de x₀
quarter-car-series-design = este ajuste, ζ { $zeta }
quarter-car-title = Suspensão de quarto de veículo
quarter-car-summary = Um canto de um carro: a carroceria (massa suspensa m) sobre uma mola k e um amortecedor c acima de uma pista fixa, deslocada de x₀ e solta a partir do repouso (x′(0) = 0). c e ζ são duas visões do mesmo amortecedor, c = 2ζ√(km): mova um e o outro acompanha; mudar m ou k mantém o amortecedor, e assim ζ muda. As curvas finas mostram os ajustes clássicos neste carro: o de conforto (ζ ≈ 0,3–0,4) tem ressalto, o esportivo (ζ ≈ 0,65–0,7) se acomoda mais rápido, e os ajustes crítico (ζ = 1) e superamortecido voltam sem ressalto, porém mais devagar. O tempo de acomodação salta quando ζ passa pelos valores em que um ressalto cai dentro da faixa: o ζ mais rápido fica logo após um desses saltos, de modo que uma carga maior pode desajustar um carro bem ajustado (veja o gráfico da massa). A acomodação é medida nesta resposta livre: o tempo de acomodação é o último instante em que |x| é igual a faixa·|x₀|, após o qual a carroceria permanece dentro de ±faixa·|x₀| em torno do repouso (e não na faixa em torno do valor final de uma resposta ao degrau).
quarter-car-param-m = massa suspensa
quarter-car-param-k = rigidez da mola
quarter-car-param-c = coeficiente do amortecedor
quarter-car-param-zeta = razão de amortecimento
quarter-car-param-x0 = deslocamento inicial
quarter-car-param-band = faixa de acomodação em torno do repouso, relativa a x₀
quarter-car-param-dm = variação da massa suspensa
quarter-car-readout-regime = regime
quarter-car-readout-wn = frequência natural ωₙ
quarter-car-readout-fn = frequência natural fₙ
quarter-car-readout-zeta = razão de amortecimento ζ
quarter-car-readout-c = coeficiente do amortecedor c em uso
quarter-car-readout-c-crit = amortecimento crítico 2√(km)
quarter-car-readout-wd = frequência amortecida ω_d
quarter-car-readout-settling-time = tempo de acomodação t_s em ±faixa·|x₀| (resposta livre)
quarter-car-readout-overshoot = ressalto máximo (relativo a x₀)
quarter-car-readout-peak-time = instante do ressalto máximo
quarter-car-readout-zeta-argmin = ζ de acomodação mais rápida (resposta livre, mesma faixa)
quarter-car-readout-settling-min = seu tempo de acomodação
quarter-car-readout-zeta-lo = ζ com massa +dm %
quarter-car-readout-zeta-hi = ζ com massa −dm %
quarter-car-plot-response = Deslocamento da carroceria x(t)
quarter-car-plot-settling = Tempo de acomodação da resposta livre em função de ζ
quarter-car-plot-sensitivity = ζ quando a massa suspensa varia
quarter-car-preset-1 = Conforto ζ = 0,3
quarter-car-preset-2 = Conforto ζ = 0,4
quarter-car-preset-3 = Esportivo ζ = 0,65
quarter-car-preset-4 = Esportivo ζ = 0,7
quarter-car-preset-5 = Crítico ζ = 1
quarter-car-preset-6 = Superamortecido ζ = 2

