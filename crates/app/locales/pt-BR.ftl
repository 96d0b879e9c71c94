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

### quarter-car-2dof

quarter-car-2dof-describe-motion = Sobre { $road ->
        [bump] uma lombada
        [step] um degrau
        [sine] uma pista senoidal
       *[random] uma pista aleatória
    } (altura máxima da pista { $road_peak }), a carroceria se desloca no máximo { $body } (em { $body_time }) e a roda no máximo { $wheel } (em { $wheel_time }).
quarter-car-2dof-describe-acceleration = A aceleração da carroceria atinge o pico de { $peak } ({ $peak_g } g); ao longo do percurso a partir do repouso, de 0 a { $window }, seu valor RMS é { $rms }.
quarter-car-2dof-describe-tyre-lift-off = A deflexão do pneu (roda acima da pista, positiva = pneu descarregando) vai de { $low } a { $high }, valor RMS { $rms }; ela atinge a deflexão estática { $limit } pela primeira vez em { $time }, quando a força do pneu cai a zero e a roda perde contato com a pista: perdas de contato { $lift_offs }; tempo fora da pista { $airborne }.
quarter-car-2dof-describe-tyre-contact = A deflexão do pneu (roda acima da pista, positiva = pneu descarregando) vai de { $low } a { $high }, valor RMS { $rms }; ela fica abaixo da deflexão estática { $limit }, de modo que o pneu mantém contato com a pista.
quarter-car-2dof-describe-frf = Resposta em frequência por unidade de altura da pista, em eixos logarítmicos. A carroceria acompanha as ondulações lentas da pista (razão 1), tem pico de { $body_peak } perto da oscilação vertical da carroceria, { $body_frequency }, e fica isolada acima disso: { $at_20 } a 20 Hz. A deflexão do pneu tem pico de { $tyre_peak } perto do salto da roda, { $tyre_frequency }.
quarter-car-2dof-schematic = Quarto de veículo em t = { $time }: carroceria { $body }, roda { $wheel }, pista { $road } (desenhadas em escala comum).
quarter-car-2dof-schematic-title = Esquema
quarter-car-2dof-axis-height = altura a partir do equilíbrio
quarter-car-2dof-axis-acceleration = aceleração z_s″
quarter-car-2dof-axis-tyre-deflection = deflexão do pneu z_u − u
quarter-car-2dof-axis-frequency = frequência f
quarter-car-2dof-axis-magnitude = magnitude por unidade de altura da pista
quarter-car-2dof-series-road = pista u
quarter-car-2dof-series-wheel = roda z_u
quarter-car-2dof-series-body = carroceria z_s
quarter-car-2dof-series-body-acceleration = aceleração da carroceria
quarter-car-2dof-series-rms = ± RMS
quarter-car-2dof-series-lift-off = perda de contato (deflexão estática)
quarter-car-2dof-series-off-road = roda fora da pista
quarter-car-2dof-series-body-gain = carroceria/pista
quarter-car-2dof-series-tyre-gain = defl. pneu/pista
quarter-car-2dof-marker-road = pista
quarter-car-2dof-title = Quarto de veículo com carroceria e roda
quarter-car-2dof-summary = Duas massas, dois modos. A carroceria (massa suspensa m_s) apoia-se na mola da suspensão k_s e no amortecedor c_s; a roda (massa não suspensa m_u) apoia-se na mola do pneu k_t, que segue a pista u(t). A oscilação vertical da carroceria, em torno de 1–1,5 Hz, é a carroceria se movendo sobre a suspensão macia; o salto da roda, em torno de 10–15 Hz, é a roda leve quicando entre o pneu rígido e a suspensão. As respostas em frequência mostram os dois: a carroceria acompanha as ondulações lentas da pista, passa por cima das rápidas e vibra mais perto da oscilação vertical; a deflexão do pneu, que decide a aderência, tem pico no salto da roda. O pneu só pode empurrar: quando a roda sobe além da sua deflexão estática, a força do pneu é zero e a roda perde contato com a pista até tocá-la de novo. O conforto é avaliado pela aceleração RMS da carroceria, e a aderência pela deflexão RMS do pneu, ambas ao longo do percurso a partir do repouso, 0 … T. A resposta é exata entre as amostras da pista, próximas o bastante para seguir cada lombada e cada salto da roda. Os deslocamentos são medidos a partir do equilíbrio estático, positivos para cima; a pista aleatória soma 64 senoides com o espectro ISO 8608 em 0,5–20 Hz. Nela, a página mostra também a aceleração RMS estacionária da carroceria na pista ISO 8608 completa, sem ponderação e ponderada pelo W_k da ISO 2631-1 (a_w, a medida de conforto), obtida da equação de Lyapunov do carro.
quarter-car-2dof-param-ms = massa da carroceria (suspensa)
quarter-car-2dof-param-mu = massa da roda (não suspensa)
quarter-car-2dof-param-ks = rigidez da suspensão
quarter-car-2dof-param-kt = rigidez do pneu
quarter-car-2dof-param-cs = amortecimento da suspensão
quarter-car-2dof-param-road = excitação da pista
quarter-car-2dof-param-road-bump = lombada única (1 − cos)
quarter-car-2dof-param-road-step = degrau (meio-fio)
quarter-car-2dof-param-road-sine = senoide
quarter-car-2dof-param-road-random = pista aleatória (ISO 8608)
quarter-car-2dof-param-h = altura da lombada ou do degrau, amplitude da senoide
quarter-car-2dof-param-L = comprimento da lombada
quarter-car-2dof-param-V = velocidade
quarter-car-2dof-param-f-road = frequência da pista senoidal
quarter-car-2dof-param-class = classe da pista aleatória
quarter-car-2dof-param-class-A = A (muito boa)
quarter-car-2dof-param-class-B = B (boa)
quarter-car-2dof-param-class-C = C (média)
quarter-car-2dof-param-class-D = D (ruim)
quarter-car-2dof-param-class-E = E (muito ruim)
quarter-car-2dof-param-class-F = F
quarter-car-2dof-param-class-G = G
quarter-car-2dof-param-class-H = H
quarter-car-2dof-param-seed = semente da pista aleatória
quarter-car-2dof-readout-f-body = frequência de oscilação vertical da carroceria [Hz]
quarter-car-2dof-readout-f-wheel = frequência de salto da roda [Hz]
quarter-car-2dof-readout-window = janela do RMS: o percurso a partir do repouso, 0 … T
quarter-car-2dof-readout-rms-body-accel = aceleração RMS da carroceria em 0 … T (conforto)
quarter-car-2dof-readout-rms-tyre-deflection = deflexão RMS do pneu z_u − u em 0 … T (aderência)
quarter-car-2dof-readout-max-travel = maior curso da suspensão |z_s − z_u|
quarter-car-2dof-readout-static-tyre-deflection = deflexão estática do pneu (além dela, a roda perde contato)
quarter-car-2dof-readout-lift-off = primeira perda de contato: a força do pneu chega a zero
quarter-car-2dof-readout-airborne-time = tempo com a roda fora da pista
quarter-car-2dof-readout-rms-road = altura RMS da pista (pista aleatória)
quarter-car-2dof-readout-stationary-accel = aceleração RMS estacionária da carroceria, pista ISO 8608 completa (pista aleatória)
quarter-car-2dof-readout-stationary-weighted-accel = a_w estacionária: aceleração RMS da carroceria ponderada pelo W_k da ISO 2631-1 (pista aleatória)
quarter-car-2dof-readout-body-gain = amplitude carroceria / pista na frequência da senoide
quarter-car-2dof-readout-tyre-gain = deflexão do pneu / amplitude da pista na frequência da senoide
quarter-car-2dof-plot-motion = Carroceria, roda e pista
quarter-car-2dof-plot-accel = Aceleração da carroceria
quarter-car-2dof-plot-frf = Resposta em frequência por unidade de altura da pista
quarter-car-2dof-plot-tyre = Deflexão do pneu
quarter-car-2dof-preset-1 = Lombada de 5 cm a 10 m/s
quarter-car-2dof-preset-2 = Meio-fio de 5 cm
quarter-car-2dof-preset-3 = Ondulação na oscilação vertical da carroceria
quarter-car-2dof-preset-4 = Ondulação no salto da roda
quarter-car-2dof-preset-5 = Pista aleatória, classe C, 20 m/s
quarter-car-2dof-preset-6 = Amortecedor macio em pista ruim

